// The court calibration page (web/court-calibration.html) in a real Chromium against a real
// `ballsight serve --sim` on 127.0.0.1: every camera's still with the reference balls found and
// named, the twelve of the simulated site found over the four cameras, a wrong ball corrected by
// a click, the calibration file the page downloads equal to the API's, a colour model learned
// from clicks, and bad input shown beside its control with nothing changed. Run from the
// repository root:
//   BALLSIGHT_BIN=build/bin/ballsight node --test tests/web/court_calibration.test.mjs
import assert from "node:assert/strict";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import test from "node:test";

import { launchBrowser, screenshotPath, watchPage } from "./browser_support.mjs";
import { startSimulatedService, until } from "./serve_support.mjs";

const court = (page) => page.evaluate(() => {
  const c = window.ballsightCourt;
  return {
    camera: c.state.camera,
    still: c.state.still,
    pose: c.posed() ? c.state.pose : null,
    posed: c.posed(),
    corrections: c.history.points,
    selected: c.state.selected,
    clicks: c.state.clicks.length,
    colours: c.state.colours,
    view: { scale: c.view.scale, tx: c.view.tx, ty: c.view.ty },
  };
});

/** Where a click at image point (x, y) lands on the page. */
async function clientOf(page, x, y) {
  const { view } = await court(page);
  const box = await page.evaluate(() => {
    const r = document.getElementById("view").getBoundingClientRect();
    const c = document.getElementById("view");
    return { left: r.left, top: r.top, sx: r.width / c.width, sy: r.height / c.height };
  });
  return [box.left + (x * view.scale + view.tx) * box.sx, box.top + (y * view.scale + view.ty) * box.sy];
}

async function posed(page, what) {
  await until(async () => (await court(page)).posed && !(await page.textContent("#status")), what);
  return court(page);
}

test("the court calibration page in Chromium", { timeout: 240_000 }, async (t) => {
  const launched = await launchBrowser(t);
  if (!launched) return;
  const { bin, browser } = launched;
  const service = await startSimulatedService(t, bin, { seconds: 200 });
  const origin = `http://127.0.0.1:${service.port}`;
  const dir = mkdtempSync(join(tmpdir(), "ballsight-court-page-"));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  const pageErrors = await watchPage(page, origin, { allowStatuses: [422] }); // the bad input's answers
  await page.goto(`${origin}/court-calibration`);
  await page.evaluate(() => window.ballsightCourt.ready);
  const site = await (await fetch(`${origin}/api/v1/court-calibration/site`)).json();
  assert.equal(site.references.length, 12);

  await t.test("finds the twelve reference balls of the simulated site, named, over the cameras", async () => {
    const found = new Map();
    for (const camera of site.cameras) {
      await page.click(`#cameras button[data-camera="${camera.name}"]`);
      await until(async () => (await court(page)).camera === camera.name, "the camera's still");
      const { pose, still } = await posed(page, `the pose of ${camera.name}`);
      assert.ok(pose, `${camera.name}: ${await page.textContent("#pose-error")}`);
      assert.equal(still.camera, camera.name);
      assert.ok(pose.matched >= 6, `${camera.name}: ${pose.matched} matched`);
      assert.ok(pose.rms_px < 1.0, `${camera.name}: rms ${pose.rms_px}`);
      for (const r of pose.references.filter((x) => x.state === "found")) {
        assert.ok(r.residual_px < 2.0, `${camera.name} ${r.name}: ${r.residual_px} px`);
        found.set(r.name, (found.get(r.name) || 0) + 1);
      }
      // The table says the same as the pose: every found ball's row says "found".
      const rows = await page.$$eval("#references tbody tr", (trs) => trs.map((tr) => [tr.dataset.name, tr.children[1].textContent]));
      assert.equal(rows.length, 12);
      for (const r of pose.references) assert.deepEqual(rows.find(([n]) => n === r.name), [r.name, r.state]);
      const shot = screenshotPath(`court-calibration-${camera.name.replace(/\W+/g, "_")}.png`);
      if (shot) await page.screenshot({ path: shot });
    }
    assert.deepEqual([...found.keys()].sort(), site.references.map((r) => r.name).sort());
  });

  await t.test("a ball marked absent and one placed by a click correct the pose; undo restores it", async () => {
    const before = (await court(page)).pose;
    const found = before.references.filter((r) => r.state === "found");
    const [gone, moved] = [found[0], found[1]];
    await page.click(`#references tr[data-name="${gone.name}"] button`);
    let now = await posed(page, "the pose without the absent ball");
    assert.equal(now.pose.references.find((r) => r.name === gone.name).state, "absent");
    assert.equal(now.selected, null, "the list's button marks the ball, it does not select it");
    assert.equal(now.pose.matched, before.matched - 1);

    // Select the other ball in the list, then click where it is (1.5 px off its blob).
    await page.click(`#references tr[data-name="${moved.name}"] td`);
    const [x, y] = [moved.seen.x_px + 1.5, moved.seen.y_px];
    const [cx, cy] = await clientOf(page, x, y);
    await page.mouse.click(cx, cy);
    now = await posed(page, "the pose with the placed ball");
    const placed = now.pose.references.find((r) => r.name === moved.name);
    assert.equal(placed.state, "placed");
    assert.ok(Math.abs(placed.seen.x_px - x) < 0.5 && Math.abs(placed.seen.y_px - y) < 0.5,
              `placed at ${JSON.stringify(placed.seen)}, clicked at ${x}, ${y}`);
    assert.ok(placed.residual_px > 0.5, `the 1.5 px shift shows in its residual: ${placed.residual_px}`);
    assert.deepEqual(now.corrections.map((c) => c.reference), [gone.name, moved.name]);

    await page.focus("#view");
    await page.keyboard.press("Control+z");
    await page.keyboard.press("Control+z");
    now = await posed(page, "the pose after undo");
    assert.deepEqual(now.corrections, []);
    assert.equal(now.pose.matched, before.matched);
    assert.equal(now.pose.rms_px, before.rms_px);
  });

  await t.test("the downloaded calibration file is the API's for the same still", async () => {
    const { still } = await court(page);
    const [file] = await Promise.all([page.waitForEvent("download"), page.click("#download")]);
    const path = join(dir, "camera.yml");
    await file.saveAs(path);
    const text = readFileSync(path, "utf8");
    const api = await fetch(`${origin}/api/v1/court-calibration/stills/${still.still}/pose?format=yaml`, { method: "POST", body: "{}" });
    assert.equal(text, await api.text());
    assert.match(text, /^%YAML:1\.0/);
    assert.match(text, /rvec: !!opencv-matrix/);
    // The simulated court has no calibration files: no save button.
    assert.equal(await page.isVisible("#save"), false);
  });

  await t.test("a colour model from clicked ball pixels", async () => {
    const { pose } = await court(page);
    await page.focus("#view");
    await page.keyboard.press("c");
    const ball = pose.references.find((r) => r.state === "found").seen;
    const [cx, cy] = await clientOf(page, ball.x_px, ball.y_px);
    await page.mouse.click(cx, cy);
    assert.equal((await court(page)).clicks, 1);
    await page.click("#learn");
    await until(async () => (await court(page)).colours !== null, "the colour model");
    const { colours } = await court(page);
    assert.equal(colours.colours.format, "ballsight-ball-colours");
    assert.ok(colours.colours.colours.length >= 1);
    assert.match(await page.textContent("#colour-info"), /balls found in this still/);
  });

  await t.test("bad input shows its error beside its control and changes nothing", async () => {
    // A click outside the image after a model was learned: refused beside Learn, the model kept.
    const learned = (await court(page)).colours;
    assert.ok(learned);
    await page.evaluate(() => window.ballsightCourt.state.clicks.push([-50, -50]));
    await page.click("#learn");
    await until(async () => page.isVisible("#colour-error"), "the colour error");
    assert.match(await page.textContent("#colour-error"), /^click 2: \(-50, -50\) lies outside the 1280x720 image$/);
    assert.deepEqual((await court(page)).colours, learned);

    // Balls marked absent until fewer than four are left: the pose's error beside the list names
    // the balls found and missing, the download is refused beside its button, and undo brings
    // the pose back.
    const before = await court(page);
    const found = before.pose.references.filter((r) => r.state === "found");
    for (const r of found.slice(3)) {
      await page.click(`#references tr[data-name="${r.name}"] button`);
      await until(async () => (await court(page)).posed && !(await page.textContent("#status")), "the pose");
    }
    assert.equal((await court(page)).pose, null);
    assert.match(await page.textContent("#pose-error"), /reference balls: found \d of 12 .*at least 4 needed; missing: /);
    await page.click("#download");
    await until(async () => page.isVisible("#save-error"), "the download's error");
    assert.match(await page.textContent("#save-error"), /at least 4 needed/);
    await page.focus("#view");
    for (const _ of found.slice(3)) await page.keyboard.press("Control+z");
    const after = await posed(page, "the pose after undo");
    assert.equal(after.pose.rms_px, before.pose.rms_px);
    assert.equal(await page.isVisible("#pose-error"), false);
    assert.equal(await page.isVisible("#save-error"), false, "the refused download's error went with its pose");
    // A still of a camera the site has not: the API's 404 naming the field.
    const answer = await fetch(`${origin}/api/v1/court-calibration/stills`, { method: "POST", body: '{"camera":"no such"}' });
    assert.equal(answer.status, 404);
    assert.equal((await answer.json()).where, "body.camera");
  });

  await t.test("usable on a tablet: no sideways scroll at 768 x 1024", async () => {
    await page.setViewportSize({ width: 768, height: 1024 });
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 0, `scrolls sideways by ${overflow} px`);
    const shot = screenshotPath("court-calibration-768x1024.png");
    if (shot) await page.screenshot({ path: shot, fullPage: true });
  });

  assert.deepEqual(pageErrors, []);
});
