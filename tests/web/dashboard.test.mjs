// The dashboard (web/index.html) in a real Chromium (Debian's, driven by playwright-core; no
// browser download) against a real `ballsight serve --sim` on 127.0.0.1. Needs scripts/setup;
// run from the repository root:
//   BALLSIGHT_BIN=build/bin/ballsight node --test tests/web/dashboard.test.mjs
// Screenshots go to $BALLSIGHT_SCREENSHOT_DIR (ctest: build/screenshots).
import assert from "node:assert/strict";
import test from "node:test";

import { launchBrowser, screenshotPath, watchPage } from "./browser_support.mjs";
import { startSimulatedService, stop, until } from "./serve_support.mjs";

test("the dashboard in Chromium", { timeout: 240_000 }, async (t) => {
  const launched = await launchBrowser(t);
  if (!launched) return;
  const { bin, browser } = launched;

  const service = await startSimulatedService(t, bin, { seconds: 120 });
  const origin = `http://127.0.0.1:${service.port}`;
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const pageErrors = await watchPage(page, origin, { allowStatuses: [401] }); // the wrong token's answer
  await page.goto(`${origin}/`);
  const shown = () => page.evaluate(() => window.ballsightDashboard);
  // A second update at least: the first subtest asks for the update shown with after = seq - 1,
  // and after = 0 asks for the latest, whatever the page shows.
  await until(async () => (await shown()).seq > 1 && (await shown()).robot, "a navigation update with the robot after the first");

  await t.test("shows exactly the balls and robot pose the API returns at that seq", async () => {
    // What the page holds and shows, read at one moment (an update may come in between reads).
    const { drawn, seqText, ballsText } = await page.evaluate(() => ({
      drawn: window.ballsightDashboard,
      seqText: document.getElementById("seq").textContent,
      ballsText: document.getElementById("balls").textContent,
    }));
    const response = await fetch(`${origin}/api/v1/navigation?after=${drawn.seq - 1}`);
    assert.equal(response.status, 200);
    const update = await response.json();
    assert.equal(update.seq, drawn.seq, "the service still keeps the update shown");
    assert.deepEqual(drawn.balls, update.world.balls);
    assert.deepEqual(drawn.robot, update.world.robot);
    assert.ok(update.world.balls.length > 0, "the simulated court has balls");
    assert.equal(seqText, String(drawn.seq));
    assert.equal(ballsText, String(update.world.balls.length));
  });

  await t.test("every ball is drawn where it lies", async () => {
    // The canvas at each ball away from the robot (drawn over the balls), read in the same task
    // as the state, so that both are of one update.
    const colours = await page.evaluate(async () => {
      const { courtTransform } = await import("/web/court_map.js");
      const site = await (await fetch("/api/v1/site")).json();
      const canvas = document.getElementById("court");
      const { balls, robot } = window.ballsightDashboard;
      const t = courtTransform(site, canvas);
      const clear = (b) => Math.hypot(b.x_m - robot.x_m, b.y_m - robot.y_m) > 0.8;
      return balls.filter(clear).map((b) => {
        const [px, py] = t.toCanvas(b.x_m, b.y_m);
        return window.pixelAt(canvas, Math.round(px), Math.round(py));
      });
    });
    assert.ok(colours.length > 0, "some balls away from the robot");
    // A ball's yellow fill (#e4f53c), its dark olive outline (#3a4a10) or a blend of the two (a
    // touching ball's outline crosses it: clusters are a few pixels apart); not the court's
    // greens (#3f7a55, #2f5a4e), a site's ring (#7fe07f) or the route (#2f6fd6).
    const ballish = ([r, g, b]) => r > 0.6 * g && b < 0.5 * g;
    for (const c of colours) assert.ok(ballish(c), `ball pixel ${c}`);
  });

  await t.test("health, cameras and the latency plot are filled in", async () => {
    await until(async () => (await page.locator("#cameras li").count()) === 4, "four cameras");
    assert.match(await page.textContent("#rate"), /\d \/s/);
    assert.match(await page.textContent("#collected"), /^\d+ \(\d+ left\)$/);
    assert.equal(await page.textContent("#connection"), "live");
    const path = screenshotPath("dashboard-1280x800.png");
    if (path) await page.screenshot({ path, fullPage: true });
  });

  await t.test("each camera's last frame with the detections the API gave for it", async () => {
    const name = "camera 1";
    const answer = await page.waitForResponse((r) => r.url().endsWith(`/api/v1/cameras/${encodeURIComponent(name)}/view`));
    const view = await answer.json();
    await until(async () => (await shown()).cameras[name]?.seq === view.seq, "the page to draw that answer");
    const drawn = (await shown()).cameras[name];
    assert.deepEqual(drawn.detections, view.detections);
    assert.equal(drawn.width, 1280);
    assert.ok(view.detections.some((d) => d.object === "ball"), "the camera sees balls");
    assert.match(view.image, /^data:image\/jpeg;base64,/);
    // The ring of the first ball is drawn in the detections' yellow on the camera's canvas.
    const ring = await page.evaluate(({ name, d }) => {
      const canvas = document.querySelector(`#camera-views canvas[data-camera="${name}"]`);
      const s = canvas.width / 1280;
      const r = Math.max(4, d.radius_px * s);
      const x = Math.round((d.x_px + 0.5) * s + r), y = Math.round((d.y_px + 0.5) * s);
      const around = [];
      for (let dx = -1; dx <= 1; ++dx) around.push(window.pixelAt(canvas, x + dx, y));
      return around;
    }, { name, d: view.detections.find((d) => d.object === "ball") });
    assert.ok(ring.some(([r, g, b]) => r > 150 && g > 150 && b < 120), `ring pixels ${JSON.stringify(ring)}`);
    await until(async () => Object.keys((await shown()).cameras).length === 4, "all four cameras");
  });

  await t.test("the planner is chosen from the page (with the token); a bad token changes nothing", async () => {
    await page.selectOption("#planner", "nearest");
    await page.fill("#token", "wrong");
    await page.click("#use-planner");
    await until(async () => page.isVisible("#planner-error"), "the planner's error");
    assert.match(await page.textContent("#planner-error"), /^headers: writes need/);
    assert.equal((await (await fetch(`${origin}/api/v1/planner`)).json()).planner, "ballsight");
    await page.fill("#token", service.token);
    await page.click("#use-planner");
    await until(async () => (await shown()).route?.planner === "nearest", "a route of the nearest planner");
    assert.equal(await page.isVisible("#planner-error"), false);
    assert.equal((await (await fetch(`${origin}/api/v1/planner`)).json()).planner, "nearest");
  });

  await t.test("a ball the robot gave up on is listed with why and crossed out on the map", async () => {
    assert.equal(await page.textContent("#given-up"), "none");
    const { balls, robot } = await shown();
    const ball = balls.find((b) => !robot || Math.hypot(b.x_m - robot.x_m, b.y_m - robot.y_m) > 1.5);
    const answer = await fetch(`${origin}/api/v1/unreachable`, {
      method: "POST",
      headers: { authorization: `Bearer ${service.token}`, "content-type": "application/json" },
      body: JSON.stringify({ balls: [{ x_m: ball.x_m, y_m: ball.y_m }], reason: "stuck at the post" }),
    });
    assert.equal(answer.status, 200);
    await until(async () => (await shown()).givenUp?.length === 1, "the mark in an update");
    assert.match(await page.textContent("#given-up"), /^-?\d+\.\d, -?\d+\.\d m: stuck at the post$/);
    // The cross's red (#d0342c) a few pixels off the ball's centre along its diagonal.
    const red = await page.evaluate(async ({ x, y }) => {
      const { courtTransform } = await import("/web/court_map.js");
      const site = await (await fetch("/api/v1/site")).json();
      const canvas = document.getElementById("court");
      const [px, py] = courtTransform(site, canvas).toCanvas(x, y);
      const found = [];
      for (let d = 3; d <= 6; ++d) found.push(window.pixelAt(canvas, Math.round(px + d), Math.round(py + d)));
      return found;
    }, { x: ball.x_m, y: ball.y_m });
    assert.ok(red.some(([r, g, b]) => r > 170 && g < 90 && b < 90), `cross pixels ${JSON.stringify(red)}`);
  });

  await t.test("fits a tablet (768 x 1024) without scrolling sideways", async () => {
    const tablet = await browser.newPage({ viewport: { width: 768, height: 1024 } });
    await tablet.goto(`${origin}/`);
    await until(async () => (await tablet.evaluate(() => window.ballsightDashboard.seq)) > 0, "an update");
    const width = await tablet.evaluate(() => document.documentElement.scrollWidth);
    assert.ok(width <= 768, `page ${width} px wide`);
    const path = screenshotPath("dashboard-768x1024.png");
    if (path) await tablet.screenshot({ path, fullPage: true });
    await tablet.close();
  });

  let errorsBeforeStop = [];
  await t.test("says so when the service goes away, and asks for no camera view meanwhile", async () => {
    errorsBeforeStop = [...pageErrors];
    await stop(service.child);
    await until(async () => /^reconnecting/.test(await page.textContent("#connection")), "reconnecting");
    // Every refused request is one error or more: none may come while the page waits, for two
    // of its camera periods (2 s each).
    const views = () => pageErrors.filter((e) => e.includes("/view")).length;
    const before = views();
    await new Promise((resolve) => setTimeout(resolve, 4500));
    assert.equal(views(), before, "camera views asked for while the service was away");
  });

  // Requests in flight or just started when the service stopped fail (the stream, a camera's
  // view: Chromium logs a refused connection as a console error); nothing else.
  assert.deepEqual(errorsBeforeStop, []);
  const afterStop = pageErrors.slice(errorsBeforeStop.length);
  const apiRequestCut = (e) =>
    e.includes("/api/v1/") && (e.startsWith("request failed: ") || e.includes("net::ERR_CONNECTION_REFUSED"));
  assert.deepEqual(afterStop.filter((e) => !apiRequestCut(e)), []);
});
