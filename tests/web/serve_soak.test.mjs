// A long run of `ballsight serve --sim`: clients of every kind connect and disconnect (stream and
// Foxglove WebSockets, long-polls, plain reads, requests cut off half-way, connections that never
// speak), while the cameras fail and return one after another. The service's open file
// descriptors must come back to what they were, its memory must stay flat, and it must exit
// cleanly (against a ballsight linked with -fsanitize=address, LeakSanitizer's check at exit is
// part of that: a leak report makes the exit status 1).
// ctest runs it for SOAK_SECONDS=20; the 10-minute soak of docs/RESULTS.md, "Long runs":
//   BALLSIGHT_BIN=build-ci/bin/ballsight SOAK_SECONDS=600 SOAK_REPORT=soak.json \
//     node --test tests/web/serve_soak.test.mjs
import assert from "node:assert/strict";
import { existsSync, readdirSync, readFileSync, writeFileSync } from "node:fs";
import { get } from "node:http";
import { connect } from "node:net";
import test from "node:test";
import { setTimeout as sleep } from "node:timers/promises";

import { startSimulatedService, until } from "./serve_support.mjs";

const SECONDS = Number(process.env.SOAK_SECONDS ?? 20);
const SAMPLE_MS = 1000;
// Memory is compared from this moment on (minute 1 of a long run): before it the pipeline and
// the clients' queues are still growing to their working size.
const WARM_S = Math.min(60, SECONDS / 4);
const modules = new URL("../../node_modules/", import.meta.url);

/** Every `period` seconds one camera in turn goes dark for half the period. */
function outages(seconds, period = 8) {
  const args = [];
  for (let i = 0; (i + 1) * period < seconds; ++i) {
    const from = i * period + 2;
    args.push("--sim-fail-camera", `${i % 4}@${from}-${from + period / 2}`);
  }
  return args;
}

function processFigures(pid) {
  const status = readFileSync(`/proc/${pid}/status`, "utf8");
  const kib = (key) => Number(new RegExp(`^${key}:\\s+(\\d+) kB`, "m").exec(status)[1]);
  return { rss_kib: kib("VmRSS"), fds: readdirSync(`/proc/${pid}/fd`).length };
}

/** GET on a connection of its own (no keep-alive: the descriptors count), the body as text. */
function read(url, { signal } = {}) {
  return new Promise((resolve, reject) => {
    const request = get(url, { agent: false, signal }, (response) => {
      let body = "";
      response.on("data", (d) => (body += d));
      response.on("end", () => resolve(body));
      response.on("error", reject);
    });
    request.on("error", reject);
  });
}

/** One round of clients; resolves when every one of them is gone. */
async function clientRound(WebSocket, port, round) {
  const base = `http://127.0.0.1:${port}/api/v1`;
  const jobs = [];
  const lifetime = () => 200 + ((round * 7919) % 1800); // ms, varied but reproducible
  // Stream clients: one closes politely, one drops its socket without a word.
  for (const polite of [true, false]) {
    jobs.push(
      new Promise((resolve) => {
        const ws = new WebSocket(`ws://127.0.0.1:${port}/api/v1/stream?topics=navigation,world,health`);
        ws.on("error", resolve);
        ws.on("close", resolve);
        ws.on("open", () => setTimeout(() => (polite ? ws.close() : ws.terminate()), lifetime()));
      }),
    );
  }
  // A Foxglove client that subscribes to every channel it is offered.
  jobs.push(
    new Promise((resolve) => {
      const ws = new WebSocket(`ws://127.0.0.1:${port}/`, ["foxglove.websocket.v1"]);
      ws.on("error", resolve);
      ws.on("close", resolve);
      ws.on("message", (data, binary) => {
        if (binary) return;
        const m = JSON.parse(data.toString());
        if (m.op !== "advertise") return;
        const subscriptions = m.channels.map((c, i) => ({ id: i + 1, channelId: c.id }));
        ws.send(JSON.stringify({ op: "subscribe", subscriptions }));
      });
      ws.on("open", () => setTimeout(() => ws.close(), lifetime()));
    }),
  );
  // Reads, a long-poll, and one request cut off before its answer.
  for (const path of ["/health", "/world", "/route", "/site", "/cameras/0/view"]) {
    jobs.push(read(base + path));
  }
  jobs.push(read(`${base}/navigation?after=1000000000&timeout_ms=300`));
  const cut = new AbortController();
  const parked = `${base}/navigation?after=1000000000&timeout_ms=5000`;
  jobs.push(read(parked, { signal: cut.signal }).catch(() => {}));
  setTimeout(() => cut.abort(), 100);
  // A connection that never speaks, and one that sends half a request.
  for (const half of ["", "GET /api/v1/health HTTP/1.1\r\nHost: x\r\n"]) {
    jobs.push(
      new Promise((resolve) => {
        const socket = connect(port, "127.0.0.1", () => {
          socket.write(half);
          setTimeout(() => socket.destroy(), lifetime());
        });
        socket.on("error", resolve);
        socket.on("close", resolve);
      }),
    );
  }
  const results = await Promise.allSettled(jobs);
  return results.filter((r) => r.status === "rejected").map((r) => String(r.reason));
}

const title = `serve --sim for ${SECONDS} s of clients coming and going`;
test(title, { timeout: (SECONDS + 120) * 1000 }, async (t) => {
  const bin = process.env.BALLSIGHT_BIN;
  if (!bin) return t.skip("BALLSIGHT_BIN is not set (the path of the ballsight executable)");
  const installed = existsSync(new URL("ws/package.json", modules));
  if (!installed && process.env.CI) {
    assert.fail("node_modules is missing: scripts/setup-npm did not run");
  }
  if (!installed) return t.skip("node_modules is missing: run scripts/setup-npm");
  const { default: WebSocket } = await import("ws");

  const service = await startSimulatedService(t, bin, {
    seconds: SECONDS + 60,
    extra: ["--balls", "30", ...outages(SECONDS)],
  });
  const pid = service.child.pid;
  const exited = new Promise((resolve) => {
    service.child.once("exit", (code, signal) => resolve({ code, signal }));
  });
  const base = `http://127.0.0.1:${service.port}/api/v1`;
  const health = async () => JSON.parse(await read(`${base}/health`));
  await until(async () => (await health()).frame_sets > 0, "a first update");
  const idle = processFigures(pid);

  const start = Date.now();
  const samples = [];
  const failures = [];
  const camerasSeenFailed = new Set();
  const sample = () => samples.push({ t_s: (Date.now() - start) / 1000, ...processFigures(pid) });
  const sampler = setInterval(sample, SAMPLE_MS);
  let rounds = 0;
  while (Date.now() - start < SECONDS * 1000) {
    failures.push(...(await clientRound(WebSocket, service.port, rounds++)));
    for (const c of (await health()).cameras) {
      if (c.state === "failed") camerasSeenFailed.add(c.name);
    }
  }
  clearInterval(sampler);
  // Every client is gone: the service's descriptors come back to what they were when idle.
  let end = processFigures(pid);
  const back = () => (end = processFigures(pid)).fds <= idle.fds;
  await until(back, `${idle.fds} open descriptors (now ${end.fds})`, 10_000);
  const last = await health();

  service.child.kill("SIGINT");
  const exit = await exited;
  const warm = samples.find((s) => s.t_s >= WARM_S) ?? samples[0];
  const report = {
    seconds: SECONDS,
    rounds,
    idle,
    warm,
    end,
    exit,
    frame_sets: last.frame_sets,
    cameras_seen_failed: [...camerasSeenFailed].sort(),
    client_errors: failures.length,
    samples,
  };
  if (process.env.SOAK_REPORT) {
    writeFileSync(process.env.SOAK_REPORT, JSON.stringify(report, null, 1) + "\n");
  }

  assert.deepEqual(failures, [], "every client got its answer or its close");
  const why = `a clean exit (a leak report under AddressSanitizer ends it with 1):\n${service.stderr()}`;
  assert.deepEqual(exit, { code: 0, signal: null }, why);
  assert.ok(rounds >= SECONDS / 4, `${rounds} rounds of clients`);
  const failing = Math.min(4, outages(SECONDS).length / 2);
  assert.equal(camerasSeenFailed.size, failing, "every camera failed in turn");
  assert.ok(last.frame_sets >= SECONDS * 5, `${last.frame_sets} updates`);
  const rss = `RSS ${end.rss_kib} KiB at the end, ${warm.rss_kib} KiB at ${warm.t_s} s`;
  assert.ok(end.rss_kib <= warm.rss_kib * 1.1, rss);
});
