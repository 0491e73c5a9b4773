// `ballsight serve --sim --record` read by Foxglove's own MCAP library (@mcap/core, what
// Foxglove and Lichtblick open files with; fzstd and lz4js decompress its chunks): the indexed
// reader (summary, chunk and message indexes, CRCs), the streaming reader, and a file whose
// writer was killed. Needs scripts/setup-npm; run from the repository root:
//   BALLSIGHT_BIN=build/bin/ballsight node --test tests/web/mcap_recording.test.mjs
import assert from "node:assert/strict";
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import test from "node:test";

import { startSimulatedService, until } from "./serve_support.mjs";

const modules = new URL("../../node_modules/", import.meta.url);
const installed = ["@mcap/core", "fzstd", "lz4js"].every((name) =>
  existsSync(new URL(`${name}/package.json`, modules)),
);
const decoder = new TextDecoder();

async function libraries(t) {
  const bin = process.env.BALLSIGHT_BIN;
  if (!bin) return t.skip("BALLSIGHT_BIN is not set (the path of the ballsight executable)");
  if (!installed && process.env.CI) assert.fail("node_modules is missing: scripts/setup-npm did not run");
  if (!installed) return t.skip("node_modules is missing: run scripts/setup-npm");
  const mcap = await import("@mcap/core");
  const { decompress: zstd } = await import("fzstd");
  const { default: lz4 } = await import("lz4js");
  const decompressHandlers = {
    zstd: (data) => zstd(data),
    lz4: (data, size) => Uint8Array.from(lz4.decompress(data, Number(size))),
  };
  return { bin, mcap, decompressHandlers };
}

/** Runs the simulated service with `extra` recording options for `seconds`; its exit code. */
async function serveAndRecord(t, bin, seconds, extra) {
  const { child } = await startSimulatedService(t, bin, { seconds, extra });
  await until(() => child.exitCode !== null || child.signalCode !== null,
    "ballsight serve to stop after its duration", 60_000);
  return child.exitCode;
}

function temporaryDirectory(t) {
  const dir = mkdtempSync(join(tmpdir(), "ballsight-mcap-"));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  return dir;
}

/** Every record of `bytes` through the streaming reader (CRCs checked), by opcode name. */
function streamRecords(mcap, bytes, decompressHandlers) {
  const reader = new mcap.McapStreamReader({ decompressHandlers, validateCrcs: true });
  reader.append(bytes);
  const records = [];
  for (let record; (record = reader.nextRecord()); ) records.push(record);
  return { records, done: reader.done() };
}

for (const compression of ["zstd", "lz4"]) {
  test(`a ${compression} recording opens in @mcap/core`, { timeout: 180_000 }, async (t) => {
    const libs = await libraries(t);
    if (!libs) return;
    const { bin, mcap, decompressHandlers } = libs;
    const path = join(temporaryDirectory(t), "run.mcap");
    const code = await serveAndRecord(t, bin, 3, ["--record", path, "--record-compression", compression]);
    assert.equal(code, 0);
    const bytes = new Uint8Array(readFileSync(path));

    const reader = await mcap.McapIndexedReader.Initialize({
      readable: new mcap.TempBuffer(bytes),
      decompressHandlers,
    });
    assert.ok(reader.chunkIndexes.length > 0, "chunk indexes");
    assert.ok(reader.chunkIndexes.every((c) => c.compression === compression));
    const topics = new Map([...reader.channelsById.values()].map((c) => [c.id, c.topic]));
    for (const topic of ["/navigation", "/balls", "/robot_pose", "/route", "/court", "/camera/camera_0/image"]) {
      assert.ok([...topics.values()].includes(topic), `channel ${topic}`);
    }
    for (const schema of reader.schemasById.values()) {
      assert.equal(schema.encoding, "jsonschema");
      JSON.parse(decoder.decode(schema.data));
    }
    const counts = new Map();
    const seqs = [];
    let images = 0;
    let dropped = 0;
    for await (const message of reader.readMessages({ validateCrcs: true })) {
      const topic = topics.get(message.channelId);
      counts.set(topic, (counts.get(topic) ?? 0) + 1);
      const body = JSON.parse(decoder.decode(message.data));
      if (topic === "/navigation") seqs.push(body.seq);
      if (topic === "/recorder") dropped = body.dropped;
      if (topic.endsWith("/image")) {
        const jpeg = Buffer.from(body.data, "base64");
        assert.deepEqual([...jpeg.subarray(0, 2)], [0xff, 0xd8], "a JPEG");
        ++images;
      }
    }
    // Every update but those the recorder says it dropped (a loaded machine), in order.
    assert.ok(seqs.length >= 3, `${seqs.length} navigation updates`);
    assert.ok(seqs.every((seq, i) => i === 0 || seq > seqs[i - 1]), "updates in order");
    assert.ok(seqs.at(-1) - seqs.length <= dropped, `${seqs.at(-1) - seqs.length} missing, ${dropped} dropped`);
    assert.equal(images, 4 * seqs.length, "four cameras' frames per update");
    assert.equal(reader.statistics.messageCount, BigInt([...counts.values()].reduce((a, b) => a + b)));
    for (const [id, count] of reader.statistics.channelMessageCounts) {
      assert.equal(count, BigInt(counts.get(topics.get(id)) ?? 0), `channel ${topics.get(id)}`);
    }
    const metadata = [];
    for await (const m of reader.readMetadata()) metadata.push(m);
    assert.equal(metadata[0].name, "ballsight");
    assert.equal(metadata[0].metadata.get("cameras").split(",").length, 4);

    const streamed = streamRecords(mcap, bytes, decompressHandlers);
    assert.ok(streamed.done, "the stream reader reaches the closing magic");
    assert.equal(streamed.records.filter((r) => r.type === "Message").length, Number(reader.statistics.messageCount));
  });
}

test("a recording whose service was killed streams up to its last chunk", { timeout: 180_000 }, async (t) => {
  const libs = await libraries(t);
  if (!libs) return;
  const { bin, mcap, decompressHandlers } = libs;
  const path = join(temporaryDirectory(t), "killed.mcap");
  const { child } = await startSimulatedService(t, bin, { extra: ["--record", path] });
  // The file begins with the replay's setup (the simulated court's four empty-court views, about
  // 5 MB); then chunks of about 1 MB.
  await until(() => existsSync(path) && statSync(path).size > 9_000_000, "three chunks on disk", 60_000);
  child.kill("SIGKILL");
  await until(() => child.exitCode !== null || child.signalCode !== null, "the killed service to exit");

  const bytes = new Uint8Array(readFileSync(path));
  await assert.rejects(mcap.McapIndexedReader.Initialize({ readable: new mcap.TempBuffer(bytes), decompressHandlers }));
  const { records, done } = streamRecords(mcap, bytes, decompressHandlers);
  assert.equal(done, false, "no closing magic");
  // The stream reader hands out a chunk's messages once the whole chunk is there (its CRC
  // checked): every update of the complete chunks, in order.
  const channels = new Map(records.filter((r) => r.type === "Channel").map((c) => [c.id, c.topic]));
  const seqs = records
    .filter((r) => r.type === "Message" && channels.get(r.channelId) === "/navigation")
    .map((r) => JSON.parse(decoder.decode(r.data)).seq);
  assert.ok(seqs.length >= 3, `${seqs.length} navigation updates`);
  assert.ok(seqs.every((seq, i) => i === 0 || seq > seqs[i - 1]), "updates in order");
});
