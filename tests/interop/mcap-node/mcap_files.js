// What the interop scripts share: reading an MCAP file with @mcap/core (every check it has, plus
// the data section CRC it leaves to the caller), and the compressors @mcap/core leaves to us.
"use strict";
const fs = require("fs");
const { McapIndexedReader, McapStreamReader } = require("@mcap/core");
const { crc32 } = require("@foxglove/crc");
const lz4js = require("lz4js");
const lz4wasm = require("@foxglove/wasm-lz4");
const zstd = require("@foxglove/wasm-zstd");

async function compressors() {
  await Promise.all([lz4wasm.isLoaded, zstd.isLoaded]);
  return {
    decompressHandlers: {
      lz4: (data, size) => lz4wasm(data, Number(size)),
      zstd: (data, size) => zstd.decompress(data, Number(size)),
    },
    compress: {
      lz4: (data) => ({ compression: "lz4", compressedData: lz4js.compress(data) }),
      zstd: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }),
    },
  };
}

class BufferWritable {
  constructor() {
    this.parts = [];
    this.size = 0n;
  }
  position() {
    return this.size;
  }
  async write(buffer) {
    this.parts.push(Buffer.from(buffer));
    this.size += BigInt(buffer.byteLength);
  }
  bytes() {
    return Buffer.concat(this.parts);
  }
}

function fail(message) {
  throw new Error(message);
}

// Reads `path` front to back (CRCs of every chunk) and through its summary and indexes, and
// checks the two agree with each other and with the statistics. Returns the schemas, channels,
// header and messages (in file order).
async function readValidated(path, decompressHandlers) {
  const bytes = fs.readFileSync(path);
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(bytes);
  const streamed = [];
  const kinds = {};
  let header, dataEnd, footer;
  for (let record; (record = stream.nextRecord()); ) {
    kinds[record.type] = (kinds[record.type] || 0) + 1;
    if (record.type === "Header") header = record;
    if (record.type === "Message") streamed.push(record);
    if (record.type === "DataEnd") dataEnd = record;
    if (record.type === "Footer") footer = record;
  }
  if (!stream.done()) fail(`${path}: the stream reader did not reach the end (${stream.bytesRemaining()} bytes left)`);
  if (!footer || !dataEnd) fail(`${path}: no Footer or DataEnd`);

  const readable = {
    size: async () => BigInt(bytes.length),
    read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
  };
  const indexed = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  const stats = indexed.statistics || fail(`${path}: no Statistics record`);
  if (indexed.chunkIndexes.length === 0) fail(`${path}: no chunk indexes`);
  if (Number(stats.messageCount) !== streamed.length) {
    fail(`${path}: statistics count ${stats.messageCount} messages, the file holds ${streamed.length}`);
  }
  if (stats.chunkCount !== indexed.chunkIndexes.length) fail(`${path}: statistics chunk count ${stats.chunkCount}`);
  if (stats.channelCount !== indexed.channelsById.size) fail(`${path}: statistics channel count ${stats.channelCount}`);
  for (const [channel, count] of stats.channelMessageCounts) {
    const actual = streamed.filter((m) => m.channelId === channel).length;
    if (Number(count) !== actual) fail(`${path}: statistics count ${count} messages on channel ${channel}, not ${actual}`);
  }
  const times = streamed.map((m) => m.logTime);
  const min = times.reduce((a, b) => (a < b ? a : b), times[0] ?? 0n);
  const max = times.reduce((a, b) => (a > b ? a : b), times[0] ?? 0n);
  if (streamed.length && (stats.messageStartTime !== min || stats.messageEndTime !== max)) {
    fail(`${path}: statistics time range ${stats.messageStartTime}..${stats.messageEndTime}, messages ${min}..${max}`);
  }
  // Through the chunk and message indexes, as a player seeking in the file reads them.
  const viaIndex = [];
  for await (const m of indexed.readMessages({ validateCrcs: true })) viaIndex.push(m);
  if (viaIndex.length !== streamed.length) fail(`${path}: the indexes reach ${viaIndex.length} of ${streamed.length} messages`);
  const key = (m) => `${m.channelId}/${m.sequence}/${m.logTime}/${Buffer.from(m.data).toString("base64")}`;
  const sortedStream = streamed.slice().sort((a, b) => (a.logTime < b.logTime ? -1 : a.logTime > b.logTime ? 1 : 0));
  for (let i = 0; i < viaIndex.length; ++i) {
    if (key(viaIndex[i]) !== key(sortedStream[i])) fail(`${path}: message ${i} read through the index differs`);
  }
  // @mcap/core leaves the data section CRC unchecked: it covers the file up to DataEnd.
  if (dataEnd.dataSectionCrc !== 0) {
    const dataEndAt = Number(footer.summaryStart) - (1 + 8 + 4);
    const crc = crc32(bytes.subarray(0, dataEndAt));
    if (crc !== dataEnd.dataSectionCrc) fail(`${path}: data section CRC ${dataEnd.dataSectionCrc}, the bytes give ${crc}`);
  }
  return { header, kinds, indexed, messages: streamed, dataSectionCrcChecked: dataEnd.dataSectionCrc !== 0 };
}

module.exports = { compressors, BufferWritable, readValidated, fail };
