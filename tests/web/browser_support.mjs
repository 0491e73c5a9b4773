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

/** Collects the page's errors, failed requests and requests to any host but `origin`. */
export function watchPage(page, origin) {
  const errors = [];
  const ws = origin.replace(/^http:/, "ws:");
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("requestfailed", (r) => errors.push(`request failed: ${r.url()}`));
  page.on("request", (r) => {
    const url = r.url();
    if (!url.startsWith(origin) && !url.startsWith(ws) && !url.startsWith("blob:"))
      errors.push(`request to another host: ${url}`);
  });
  return errors;
}
