// ballsight's Foxglove WebSocket server (src/ballsight/net/foxglove.cpp) against the official
// client, @foxglove/ws-protocol over ws, on the simulated court and on a recording of it served
// again (`serve --replay`). Needs scripts/setup-npm; run from the repository root:
//   BALLSIGHT_BIN=build/bin/ballsight node --test tests/web/foxglove_conformance.test.mjs
import assert from "node:assert/strict";
import { existsSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import test from "node:test";
import { setTimeout as sleep } from "node:timers/promises";

import { startService, until } from "./serve_support.mjs";

const TOPICS = ["/court", "/balls", "/robot_pose", "/route", "/navigation"];
const modules = new URL("../../node_modules/", import.meta.url);
const decoder = new TextDecoder();

/** Timestamps strictly increasing. */
function assertIncreasing(messages, what) {
  for (let i = 1; i < messages.length; ++i) {
    const [a, b] = [messages[i - 1].timestamp, messages[i].timestamp];
    assert.ok(b > a, `${what}: timestamp ${b} after ${a} (message ${i})`);
  }
}

const installed = ["@foxglove/ws-protocol", "ws"].every((name) =>
  existsSync(new URL(`${name}/package.json`, modules)),
);

/** The executable, or a skip (a failure in CI when the packages are missing). */
function executable(t) {
  const bin = process.env.BALLSIGHT_BIN;
  if (!bin) return t.skip("BALLSIGHT_BIN is not set (the path of the ballsight executable)");
  // CI installs the packages (scripts/setup): there a missing client is a failure, not a skip.
  if (!installed && process.env.CI) assert.fail("node_modules is missing: scripts/setup-npm did not run");
  if (!installed) return t.skip("node_modules is missing: run scripts/setup-npm");
  return bin;
}

test("Foxglove WebSocket v1 with @foxglove/ws-protocol", { timeout: 180_000 }, async (t) => {
  const bin = executable(t);
  if (bin) await conformance(t, bin, ["--sim"]);
});

// A recording of the simulated court served again: the same channels and stream, from the file.
test("the same in replay (serve --replay)", { timeout: 180_000 }, async (t) => {
  const bin = executable(t);
  if (!bin) return;
  const dir = mkdtempSync(join(tmpdir(), "ballsight-replay-"));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const file = join(dir, "run.mcap");
  const { child } = await startService(t, bin, {
    court: ["--sim"], seconds: 8, extra: ["--record", file],
  });
  await until(() => child.exitCode !== null, "the recording service to stop after 8 s", 60_000);
  assert.equal(child.exitCode, 0);
  // Recorded at 10 updates a second, replayed at half that pace: some 16 s of stream.
  await conformance(t, bin, ["--replay", file, "--speed", "0.5"]);
});

async function conformance(t, bin, court) {
  const { default: protocol } = await import("@foxglove/ws-protocol"); // CJS
  const { FoxgloveClient } = protocol;
  const { default: WebSocket } = await import("ws");

  const { port } = await startService(t, bin, { court });
  const url = `ws://127.0.0.1:${port}/`;

  const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const client = new FoxgloveClient({ ws });
  t.after(() => client.close());
  const seen = { serverInfo: null, channels: null, errors: [], statuses: [], inbox: new Map() };
  client.on("serverInfo", (info) => (seen.serverInfo = info));
  client.on("advertise", (channels) => (seen.channels = channels));
  client.on("error", (e) => seen.errors.push(e));
  client.on("status", (s) => seen.statuses.push(s));
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    if (!seen.inbox.has(subscriptionId)) seen.inbox.set(subscriptionId, []);
    try {
      seen.inbox.get(subscriptionId).push({ timestamp, payload: JSON.parse(decoder.decode(data)) });
    } catch (e) {
      seen.errors.push(new Error(`subscription ${subscriptionId}: payload is not JSON: ${e}`));
    }
  });
  const inbox = (id) => seen.inbox.get(id) ?? [];
  const channel = (topic) => {
    const found = seen.channels?.find((c) => c.topic === topic);
    assert.ok(found, `${topic} is advertised`);
    return found;
  };

  await t.test("serverInfo, then an advertise of the JSON channels", async () => {
    await until(() => seen.serverInfo, "serverInfo");
    assert.equal(seen.serverInfo.name, "ballsight");
    assert.ok(Array.isArray(seen.serverInfo.capabilities));
    assert.equal(ws.protocol, "foxglove.websocket.v1");
    await until(() => seen.channels, "advertise");
    assert.deepEqual(seen.channels.map((c) => c.topic).sort(), [...TOPICS].sort());
    for (const c of seen.channels) {
      assert.equal(typeof c.id, "number", c.topic);
      assert.equal(c.encoding, "json", c.topic);
      assert.equal(c.schemaEncoding, "jsonschema", c.topic);
      assert.ok(c.schemaName, c.topic);
      assert.equal(typeof JSON.parse(c.schema), "object", c.topic);
    }
  });

  await t.test("/court is a foxglove.SceneUpdate with lines", async () => {
    const court = channel("/court");
    assert.equal(court.schemaName, "foxglove.SceneUpdate");
    const id = client.subscribe(court.id);
    await until(() => inbox(id).length > 0, "a /court message");
    const { entities } = inbox(id)[0].payload;
    assert.ok(Array.isArray(entities) && entities.length > 0, "entities");
    const lines = entities.flatMap((e) => e.lines ?? []);
    assert.ok(lines.length > 0, "an entity with lines");
    assert.ok(lines.every((l) => l.points.length >= 2), "every line has points");
    client.unsubscribe(id);
  });

  let navigation, route;
  await t.test("/navigation and /route stream in order, without gaps", async () => {
    navigation = client.subscribe(channel("/navigation").id);
    route = client.subscribe(channel("/route").id);
    await until(
      () => inbox(navigation).length >= 4 && inbox(route).length >= 3,
      "4 /navigation and 3 /route messages",
    );
    assertIncreasing(inbox(navigation), "/navigation");
    assertIncreasing(inbox(route), "/route");
    const seqs = inbox(navigation).map((m) => m.payload.seq);
    seqs.slice(1).forEach((s, i) => assert.equal(s, seqs[i] + 1, `seq after ${seqs[i]}: ${seqs}`));
    for (const { timestamp, payload } of inbox(route)) {
      const { sec, nsec } = payload.timestamp;
      assert.equal(BigInt(sec) * 1_000_000_000n + BigInt(nsec), timestamp, "stamp = frame time");
      assert.ok(Array.isArray(payload.poses), "poses");
    }
  });

  await t.test("unsubscribe ends a subscription", async () => {
    assert.ok(inbox(navigation).length && inbox(route).length, "/navigation and /route running");
    client.unsubscribe(navigation);
    await sleep(500); // what was in flight
    const [navigations, routes] = [inbox(navigation).length, inbox(route).length];
    await until(() => inbox(route).length >= routes + 3, "3 more /route messages");
    assert.equal(inbox(navigation).length, navigations, "no /navigation after unsubscribe");
    client.unsubscribe(route);
  });

  await t.test("no client errors, no error statuses", () => {
    assert.deepEqual(seen.errors.map(String), []);
    assert.deepEqual(seen.statuses.filter((s) => s.level >= 2), []);
  });

  await t.test("foxglove.sdk.v1 is selected when offered", async (st) => {
    const raw = new WebSocket(url, ["foxglove.sdk.v1"]);
    st.after(() => raw.terminate());
    let first = null;
    raw.once("message", (data, binary) => (first = { data, binary }));
    raw.on("error", (e) => seen.errors.push(e));
    await until(() => first || seen.errors.length, "the first message on foxglove.sdk.v1");
    assert.deepEqual(seen.errors.map(String), []);
    assert.equal(raw.protocol, "foxglove.sdk.v1");
    assert.equal(first.binary, false);
    assert.equal(JSON.parse(first.data.toString()).op, "serverInfo");
  });
}
