// Shared by the browser tests: Debian's Chromium through playwright-core (no browser download),
// with its background services off, and the screenshots' folder.
import assert from "node:assert/strict";
import { existsSync, mkdirSync } from "node:fs";
import { join } from "node:path";

const CHROMIUM = "/usr/bin/chromium";
// No traffic but to the page's own server: Chromium's background services stay off.
const CHROMIUM_ARGS = [
  "--no-sandbox",
  "--disable-gpu",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
  "--disable-default-apps",
  "--disable-extensions",
];
const installed = existsSync(new URL("../../node_modules/playwright-core/package.json", import.meta.url));

export function screenshotPath(name) {
  const dir = process.env.BALLSIGHT_SCREENSHOT_DIR;
  if (!dir) return null;
  mkdirSync(dir, { recursive: true });
  return join(dir, name);
}

/**
 * The ballsight executable and a headless Chromium for the test `t` (closed at its end), or null
 * when the test was skipped: BALLSIGHT_BIN unset, or (outside CI) no browser installed.
 */
export async function launchBrowser(t) {
  const bin = process.env.BALLSIGHT_BIN;
  if (!bin) {
    t.skip("BALLSIGHT_BIN is not set (the path of the ballsight executable)");
    return null;
  }
  const ready = installed && existsSync(CHROMIUM);
  // CI installs both (scripts/setup): there a missing browser is a failure, not a skip.
  if (!ready && process.env.CI) assert.fail(`playwright-core or ${CHROMIUM} is missing: scripts/setup did not run`);
  if (!ready) {
    t.skip(`playwright-core or ${CHROMIUM} is missing: run scripts/setup`);
    return null;
  }
  const { chromium } = await import("playwright-core");
  const browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS });
  t.after(() => browser.close());
  return { bin, browser };
}

/**
 * Collects the page's errors, its console's errors and warnings, failed requests and requests to
 * any host but `origin`. A page shows no console error or warning in normal use; the one a test
 * provokes on purpose is Chromium's note of an API answer with a status of `allowStatuses` (the
 * page shows that error beside its control, and the test checks it there).
 */
export async function watchPage(page, origin, { allowStatuses = [] } = {}) {
  const errors = [];
  // The tests read canvas pixels with window.pixelAt(canvas, x, y) -> [r, g, b, a]: through a
  // 1x1 canvas made for reading, so that the page's own canvases are never read back (Chromium
  // warns of repeated getImageData on a canvas not made for it).
  await page.addInitScript(() => {
    window.pixelAt = (canvas, x, y) => {
      const scratch = document.createElement("canvas");
      scratch.width = scratch.height = 1;
      const ctx = scratch.getContext("2d", { willReadFrequently: true });
      ctx.drawImage(canvas, x, y, 1, 1, 0, 0, 1, 1);
      return Array.from(ctx.getImageData(0, 0, 1, 1).data);
    };
  });
  const ws = origin.replace(/^http/, "ws");
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (message) => {
    if (message.type() !== "error" && message.type() !== "warning") return;
    const status = /the server responded with a status of (\d+)/.exec(message.text());
    if (status && allowStatuses.includes(Number(status[1]))) return;
    errors.push(`console ${message.type()}: ${message.text()} (${message.location().url})`);
  });
  page.on("requestfailed", (r) => errors.push(`request failed: ${r.url()}`));
  page.on("request", (r) => {
    const url = r.url();
    if (!url.startsWith(origin) && !url.startsWith(ws) && !url.startsWith("blob:") && !url.startsWith("data:"))
      errors.push(`request to another host: ${url}`);
  });
  page.on("response", (r) => {
    if (r.status() === 404 && !allowStatuses.includes(404)) errors.push(`404: ${r.url()}`);
  });
  return errors;
}
