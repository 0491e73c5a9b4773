// Shared by the web tests: a `ballsight serve --sim` on 127.0.0.1 and a free port, stopped when
// the test ends, and bounded waits.
import { spawn } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { createInterface } from "node:readline";
import { setTimeout as sleep } from "node:timers/promises";

export const WAIT_MS = 20_000; // every wait is bounded by this

/** Polls `done` (may be async) until it is truthy, or fails after `ms` naming `what`. */
export async function until(done, what, ms = WAIT_MS) {
  const end = Date.now() + ms;
  while (!(await done())) {
    if (Date.now() > end) throw new Error(`timed out after ${ms} ms waiting for ${what}`);
    await sleep(50);
  }
}

/** The port of `ballsight serve`, from its "ballsight serve: http://127.0.0.1:PORT/..." line. */
function listeningPort(child, stderr) {
  return new Promise((resolve, reject) => {
    const fail = (error) => {
      clearTimeout(timer);
      reject(error);
    };
    const timer = setTimeout(() => fail(new Error(`no listening line in ${WAIT_MS} ms`)), WAIT_MS);
    createInterface({ input: child.stdout }).on("line", (line) => {
      const m = /^ballsight serve: http:\/\/127\.0\.0\.1:(\d+)\//.exec(line);
      if (!m) return;
      clearTimeout(timer);
      resolve(Number(m[1]));
    });
    child.once("error", fail);
    child.once("exit", (code, signal) => {
      fail(new Error(`ballsight exited (${code ?? signal}) before listening:\n${stderr()}`));
    });
  });
}

/** SIGTERM, then SIGKILL if it has not exited within 10 s. */
export async function stop(child) {
  if (child.exitCode !== null || child.signalCode !== null) return;
  const exited = new Promise((resolve) => child.once("exit", resolve));
  child.kill("SIGTERM");
  const timer = setTimeout(() => child.kill("SIGKILL"), 10_000);
  await exited;
  clearTimeout(timer);
}

/**
 * Starts `bin serve --sim --listen 127.0.0.1:0 --duration SECONDS` (plus `extra` arguments) for
 * the test `t`, which stops it at its end. Returns {child, port, token, stderr()}.
 */
export async function startSimulatedService(t, bin, { seconds = 60, extra = [] } = {}) {
  return startService(t, bin, { court: ["--sim"], seconds, extra });
}

/** The same for any court: `court` is `["--sim"]`, `["--replay", FILE, "--speed", X]`, ... */
export async function startService(t, bin, { court, seconds = 60, extra = [] }) {
  const dir = mkdtempSync(join(tmpdir(), "ballsight-web-"));
  const args = ["serve", ...court, "--listen", "127.0.0.1:0", "--duration", String(seconds)];
  args.push("--token-file", join(dir, "token"), ...extra);
  const child = spawn(bin, args, { stdio: ["ignore", "pipe", "pipe"] });
  let stderr = "";
  child.stderr.on("data", (d) => (stderr = (stderr + d).slice(-4000)));
  t.after(async () => {
    await stop(child);
    rmSync(dir, { recursive: true, force: true });
  });
  const port = await listeningPort(child, () => stderr);
  const token = readFileSync(join(dir, "token"), "utf8").split("\n")[0];
  return { child, port, token, stderr: () => stderr };
}
