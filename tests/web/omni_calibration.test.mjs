// The omni calibration page (web/omni-calibration.html) in a real Chromium against a real
// `ballsight serve --sim` on 127.0.0.1: clicks land on the image pixel under them at any zoom,
// the markers found become points, a fit from the page gives the table `ballsight omni fit`
// makes of the exported samples, and a bad upload is shown and changes nothing. Run from the
// repository root:
//   BALLSIGHT_BIN=build/bin/ballsight node --test tests/web/omni_calibration.test.mjs
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import test from "node:test";

import { launchBrowser, screenshotPath, watchPage } from "./browser_support.mjs";
import { startSimulatedService, until } from "./serve_support.mjs";

const omni = (page) => page.evaluate(() => ({
  frame: window.ballsightOmni.state.frame,
  center: window.ballsightOmni.state.center,
  points: window.ballsightOmni.points(),
  candidates: window.ballsightOmni.state.candidates.length,
  view: { scale: window.ballsightOmni.view.scale, tx: window.ballsightOmni.view.tx, ty: window.ballsightOmni.view.ty },
}));

/** Where a click at image point (x, y) lands on the page, from the view's scale and offset. */
async function clientOf(page, x, y) {
  const { view } = await omni(page);
  const box = await page.evaluate(() => {
    const c = document.getElementById("view");
    const r = c.getBoundingClientRect();
    return { left: r.left, top: r.top, sx: r.width / c.width, sy: r.height / c.height };
  });
  return [box.left + (x * view.scale + view.tx) * box.sx, box.top + (y * view.scale + view.ty) * box.sy];
}

async function download(page, button, path) {
  const [file] = await Promise.all([page.waitForEvent("download"), page.click(button)]);
  await file.saveAs(path);
  return readFileSync(path);
}

test("the omni calibration page in Chromium", { timeout: 240_000 }, async (t) => {
  const launched = await launchBrowser(t);
  if (!launched) return;
  const { bin, browser } = launched;
  const service = await startSimulatedService(t, bin, { seconds: 200 });
  const origin = `http://127.0.0.1:${service.port}`;
  const dir = mkdtempSync(join(tmpdir(), "ballsight-omni-page-"));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  const pageErrors = await watchPage(page, origin, { allowStatuses: [415, 422] }); // the bad uploads' answers
  await page.goto(`${origin}/omni-calibration`);
  await page.evaluate(() => window.ballsightOmni.ready);

  const badUpload = { name: "notes.png", mimeType: "image/png", buffer: Buffer.from("not an image at all") };

  await t.test("a bad upload shows its error and changes nothing", async () => {
    await page.setInputFiles("#upload", badUpload);
    await until(async () => page.isVisible("#upload-error"), "the upload's error");
    assert.match(await page.textContent("#upload-error"), /^body: not a PNG or JPEG image/);
    assert.equal((await omni(page)).frame, null);
  });

  await t.test("opens the simulated robot's calibration frame with the rim's centre", async () => {
    await page.click("#open-sim");
    await until(async () => (await omni(page)).frame !== null, "the frame");
    const { frame, center } = await omni(page);
    assert.equal(frame.width, 640);
    assert.ok(frame.rim, "a rim suggestion");
    assert.deepEqual(center, [frame.rim.x_px, frame.rim.y_px]);
    assert.equal(await page.isVisible("#upload-error"), false);
  });

  await t.test("a click adds a point at the image pixel under it, at any zoom", async () => {
    // Zoom with the keys (1.25 each, about the canvas's middle), then click at an image point
    // near the middle, off the centre's cross, where it is drawn.
    for (const [zoomSteps, offset] of [[0, [-69.7, -59.3]], [4, [13.6, -9.4]], [9, [-7.55, 6.2]]]) {
      await page.focus("#view");
      const start = (await omni(page)).view.scale;
      for (let i = 0; i < zoomSteps; ++i) await page.keyboard.press("+");
      await until(async () => Math.abs((await omni(page)).view.scale / (start * 1.25 ** zoomSteps) - 1) < 1e-9, "the zoom");
      const v = (await omni(page)).view;
      const x = (400 - v.tx) / v.scale + offset[0], y = (300 - v.ty) / v.scale + offset[1];
      const [cx, cy] = await clientOf(page, x, y);
      const before = (await omni(page)).points.length;
      await page.mouse.click(cx, cy);
      await until(async () => (await omni(page)).points.length === before + 1, "the new point");
      const { points, view } = await omni(page);
      const p = points[points.length - 1];
      assert.ok(Math.hypot(p.x_px - x, p.y_px - y) <= 0.5, `at scale ${view.scale}: (${p.x_px}, ${p.y_px}) for (${x}, ${y})`);
      assert.ok(p.distance_cm >= 60 && p.distance_cm <= 460, "a ring of the layout suggested");
      if (view.scale >= 2) {
        // The image is drawn under the transform the click used: the canvas there shows the
        // frame's own pixel (without smoothing at this zoom), away from the drawn point.
        const same = await page.evaluate(async ([x, y]) => {
          const { view, state } = window.ballsightOmni;
          const img = new OffscreenCanvas(state.frame.width, state.frame.height).getContext("2d");
          img.drawImage(state.bitmap, 0, 0);
          const want = img.getImageData(Math.round(x) + 3, Math.round(y), 1, 1).data;
          const [cx, cy] = view.canvasFromImage(Math.round(x) + 3, Math.round(y));
          const got = window.pixelAt(document.getElementById("view"), Math.floor(cx), Math.floor(cy));
          return Array.from(want).join() === Array.from(got).join();
        }, [x, y]);
        assert.ok(same, "the canvas shows the frame's pixel where the click maps");
      }
    }
    await page.focus("#view");
    await page.keyboard.press("0");  // back to the whole frame
  });

  await t.test("undo, redo and drag", async () => {
    await page.focus("#view");
    const n = (await omni(page)).points.length;
    await page.keyboard.press("Control+z");
    assert.equal((await omni(page)).points.length, n - 1);
    await page.keyboard.press("Control+y");
    assert.equal((await omni(page)).points.length, n);
    const p = (await omni(page)).points[0];
    const [sx, sy] = await clientOf(page, p.x_px, p.y_px);
    const [ex, ey] = await clientOf(page, p.x_px + 20, p.y_px - 10);
    await page.mouse.move(sx, sy);
    await page.mouse.down();
    await page.mouse.move(ex, ey, { steps: 5 });
    await page.mouse.up();
    const q = (await omni(page)).points[0];
    assert.ok(Math.hypot(q.x_px - p.x_px - 20, q.y_px - p.y_px + 10) <= 0.5, `dragged to (${q.x_px}, ${q.y_px})`);
    await page.keyboard.press("Control+z");
    assert.deepEqual((await omni(page)).points[0], p);
    // The clicked points go; the markers come.
    for (let i = 0; i < n; ++i) {
      await page.click("#points tbody tr:first-child td:first-child");
      await page.click("#delete-point");
    }
    assert.equal((await omni(page)).points.length, 0);
  });

  let exported;
  await t.test("markers found and accepted, fitted, the table is omni fit's on the export", async () => {
    await page.click("#find-markers");
    await until(async () => (await omni(page)).candidates > 0, "marker candidates");
    const found = (await omni(page)).candidates;
    assert.ok(found >= 300, `${found} of 324 markers found`);
    await page.click("#accept-all");
    assert.equal((await omni(page)).points.length, found);
    await page.selectOption("#method", "poly");
    await page.click("#fit");
    await until(async () => /^poly on \d+ points/.test(await page.textContent("#fit-info")), "the fit", 120_000);
    const residuals = await page.locator("#points tbody tr td:last-child").allTextContents();
    assert.ok(residuals.every((r) => /^-?\d+\.\d\d$/.test(r)), "every point's residual shown");
    // The curves plotted by uPlot (npm) are the fit's: 12 directions and the points.
    await until(async () => page.evaluate(() => window.ballsightOmni.state.plot !== null), "the plot");
    const plotted = await page.evaluate(() => {
      const { plot, fit } = window.ballsightOmni.state;
      const curve = fit.result.curves[3];
      const x = plot.data[0].indexOf(curve.radius_px[10]);
      return { series: plot.series.length, value: plot.data[4][x], expected: curve.distance_cm[10],
               points: plot.data[13].filter((v) => v !== null).length };
    });
    assert.equal(plotted.series, 1 + 12 + 1);
    assert.equal(plotted.value, plotted.expected);
    assert.ok(plotted.points > 0.9 * found, `${plotted.points} points plotted`);
    assert.equal(await page.locator("#curves canvas").count(), 1);
    assert.equal(await page.isVisible("#curves-error"), false);

    const csv = join(dir, "samples.csv");
    exported = await download(page, "#export-csv", csv);
    const table = await download(page, "#export-table", join(dir, "page.bsmap"));
    const { center } = await omni(page);
    const cli = join(dir, "cli.bsmap");
    execFileSync(bin, ["omni", "fit", "--samples", csv, "--method", "poly", "--center", `${center[0]},${center[1]}`,
                       "--image-size", "640x480", "--out", cli]);
    assert.ok(table.equals(readFileSync(cli)), "the page's table is byte for byte omni fit's");
    const iris = await download(page, "#export-iris", join(dir, "px2cm.bin"));
    assert.equal(iris.length, 360 * 3200 * 2);
    const path = screenshotPath("omni-calibration-1280x800.png");
    if (path) {
      await page.check("#heatmap");
      await page.screenshot({ path, fullPage: true });
    }
  });

  await t.test("a table checked against the points; one for another image size is refused", async () => {
    const { center } = await omni(page);
    const other = join(dir, "other.bsmap");
    execFileSync(bin, ["omni", "fit", "--samples", join(dir, "samples.csv"), "--method", "poly", "--center",
                       `${2 * center[0]},${2 * center[1]}`, "--image-size", "1280x960", "--out", other]);
    await page.setInputFiles("#check-table", { name: "other.bsmap", mimeType: "application/octet-stream", buffer: readFileSync(other) });
    await until(async () => page.isVisible("#table-error"), "the table's error");
    assert.match(await page.textContent("#table-error"), /^body: image size 1280x960 does not match 640x480$/);
    assert.equal(await page.evaluate(() => window.ballsightOmni.state.checked), null);
    // The page's own table: its residuals are the fit's (the table holds the fit, read bilinearly).
    await page.setInputFiles("#check-table", { name: "page.bsmap", mimeType: "application/octet-stream", buffer: readFileSync(join(dir, "page.bsmap")) });
    await until(async () => page.evaluate(() => window.ballsightOmni.state.checked !== null), "the table's check");
    assert.equal(await page.isVisible("#table-error"), false);
    const { check, fitMedian } = await page.evaluate(() => ({
      check: window.ballsightOmni.state.checked.check,
      fitMedian: window.ballsightOmni.state.fit.result.errors.distance_cm.median,
    }));
    assert.ok(Math.abs(check.distance_cm.median - fitMedian) < 0.2, `table ${check.distance_cm.median} cm, fit ${fitMedian} cm`);
    assert.match(await page.textContent("#table-info"), /^page\.bsmap \(poly, 640 × 480\) on \d+ points: distance error median/);
  });

  await t.test("a bad upload after work changes nothing; an import brings the points back", async () => {
    const before = await omni(page);
    await page.setInputFiles("#upload", badUpload);
    await until(async () => page.isVisible("#upload-error"), "the upload's error");
    const after = await omni(page);
    assert.deepEqual(after.frame, before.frame);
    assert.deepEqual(after.points, before.points);
    await page.setInputFiles("#import-csv", { name: "bad.csv", mimeType: "text/csv", buffer: Buffer.from("a,b\n1,2\n") });
    await until(async () => page.isVisible("#import-error"), "the import's error");
    assert.deepEqual((await omni(page)).points, before.points);
    // The export, imported on a fresh page of the same frame, gives the same points.
    const fresh = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await fresh.goto(`${origin}/omni-calibration`);
    await fresh.evaluate(() => window.ballsightOmni.ready);
    await fresh.click("#open-sim");
    await until(async () => (await omni(fresh)).frame !== null, "the frame");
    await fresh.setInputFiles("#import-csv", { name: "samples.csv", mimeType: "text/csv", buffer: exported });
    await until(async () => (await omni(fresh)).points.length > 0 || (await fresh.isVisible("#import-error")), "the import");
    assert.equal(await fresh.isVisible("#import-error"), false, await fresh.textContent("#import-error"));
    const imported = (await omni(fresh)).points;
    assert.equal(imported.length, before.points.length);
    imported.forEach((p, i) => assert.ok(Math.hypot(p.x_px - before.points[i].x_px, p.y_px - before.points[i].y_px) < 1e-6));
    await fresh.close();
  });

  await t.test("fits a tablet (768 x 1024) without scrolling sideways", async () => {
    const tablet = await browser.newPage({ viewport: { width: 768, height: 1024 } });
    await tablet.goto(`${origin}/omni-calibration`);
    await tablet.evaluate(() => window.ballsightOmni.ready);
    await tablet.click("#open-sim");
    await until(async () => (await omni(tablet)).frame !== null, "the frame");
    const width = await tablet.evaluate(() => document.documentElement.scrollWidth);
    assert.ok(width <= 768, `page ${width} px wide`);
    const path = screenshotPath("omni-calibration-768x1024.png");
    if (path) await tablet.screenshot({ path, fullPage: true });
    await tablet.close();
  });

  assert.deepEqual(pageErrors, []);
});
