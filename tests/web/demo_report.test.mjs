// `ballsight demo`'s report.html opened from its folder (file://, no server) in a real Chromium
// (Debian's, driven by playwright-core): no console error, the result before any section, every
// thumbnail opening its picture, nothing wider than a tablet held upright, and the closed loop's
// replay: the slider moves the robot along its true path and takes the collected balls away, and
// play runs the clock. Screenshots go to $BALLSIGHT_SCREENSHOT_DIR (ctest: build/screenshots).
//   BALLSIGHT_BIN=build/bin/ballsight node --test tests/web/demo_report.test.mjs
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import test from "node:test";
import { pathToFileURL } from "node:url";

import { launchBrowser, screenshotPath, watchPage } from "./browser_support.mjs";
import { until } from "./serve_support.mjs";

test("the demo's report in Chromium, from its folder", { timeout: 600_000 }, async (t) => {
  const launched = await launchBrowser(t);
  if (!launched) return;
  const { bin, browser } = launched;
  const dir = mkdtempSync(join(tmpdir(), "ballsight-report-"));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  // A small demo: one omni frame, three balls, no run with faults.
  const demo = spawnSync(
    bin,
    ["demo", "--out", dir, "--omni-frames", "1", "--loop-balls", "3", "--loop-max-time", "60", "--no-faults"],
    { encoding: "utf8", timeout: 500_000 },
  );
  assert.equal(demo.status, 0, `ballsight demo failed: ${demo.stderr}`);

  for (const [name, viewport] of [
    ["1280", { width: 1280, height: 900 }],
    ["tablet", { width: 820, height: 1180 }],
  ]) {
    await t.test(`at ${viewport.width} px`, async () => {
      const page = await browser.newPage({ viewport });
      const errors = await watchPage(page, "file://");
      await page.goto(pathToFileURL(join(dir, "report.html")).href);
      await until(
        () => page.evaluate(() => document.getElementById("loop-replay")?.dataset.robot),
        "the replay to draw its first moment",
      );
      const layout = await page.evaluate(() => ({
        first: document.querySelector("main > section")?.id,
        sections: document.querySelectorAll("main > section").length,
        tables: document.querySelectorAll("main table").length,
        overflow: document.documentElement.scrollWidth - window.innerWidth,
        thumbs: Array.from(document.querySelectorAll(".thumbs img")).map((img) => ({
          src: img.getAttribute("src"),
          link: img.closest("a")?.getAttribute("href"),
        })),
      }));
      assert.equal(layout.first, "result", "the report opens with the result");
      assert.ok(layout.sections >= 6 && layout.tables >= 5, JSON.stringify(layout));
      assert.ok(layout.overflow <= 0, `the page is ${layout.overflow} px wider than the window`);
      assert.ok(layout.thumbs.length > 10);
      for (const { src, link } of layout.thumbs) assert.equal(link, src, "the thumbnail opens its picture");

      await page.locator("#loop-replay").scrollIntoViewIfNeeded();
      const state = () =>
        page.evaluate(() => ({
          robot: document.getElementById("loop-replay").dataset.robot,
          clock: document.querySelector("#loop-replay output").value,
          time: Number(document.querySelector("#loop-replay input").value),
          end: Number(document.querySelector("#loop-replay input").max),
        }));
      const setTime = (seconds) =>
        page.evaluate((value) => {
          const slider = document.querySelector("#loop-replay input");
          slider.value = String(value);
          slider.dispatchEvent(new Event("input", { bubbles: true }));
        }, seconds);
      const start = await state();
      assert.ok(start.end > 5, `the run lasted ${start.end} s`);
      assert.match(start.clock, /^0\.0 s of .*: 3 of 3 balls left$/);
      // The slider to the end: the robot elsewhere, every ball collected (ballsight's run).
      await page.selectOption("#loop-replay select", { label: "ballsight" });
      const begun = await state();
      await setTime(begun.end);
      const end = await state();
      assert.notEqual(end.robot, begun.robot, "the slider moved the robot");
      assert.match(end.clock, /: 0 of 3 balls left$/);
      // Play from the start: the clock runs.
      await setTime(0);
      await page.click("#loop-replay button");
      await until(async () => (await state()).time > 1, "the replay to play");
      await page.click("#loop-replay button"); // pause
      await page.locator("#loop-replay canvas").scrollIntoViewIfNeeded();
      const shot = screenshotPath(`demo-report-${name}.png`);
      if (shot) await page.screenshot({ path: shot });
      assert.deepEqual(errors, []);
      await page.close();
    });
  }
});
