// Writes, with @mcap/core and @foxglove/rosmsg2-serialization, MCAP recordings of PointCloud2
// messages in several layouts, and for each message a PCD file of the very same points.
//   node write_clouds.js OUT_DIR CLOUD.xyz...
// Recordings (one message per cloud, 0.2 s apart, and a std_msgs/String on /rosout between):
//   lz4_float32.mcap, zstd_float64_organized.mcap, zstd_float32_organized.mcap, lz4_float64.mcap
// PCDs: <recording>_<k>.pcd (binary; F4 or F8 as the message; organized ones keep their grid).
"use strict";
const fs = require("fs");
const path = require("path");
const { McapWriter } = require("@mcap/core");
const { parse } = require("@foxglove/rosmsg");
const { MessageWriter } = require("@foxglove/rosmsg2-serialization");
const { compressors, BufferWritable } = require("./mcap_files");

// The ROS 2 definition, written here independently of cloudshape's copy.
const POINTCLOUD2 = `std_msgs/Header header
uint32 height
uint32 width
PointField[] fields
bool is_bigendian
uint32 point_step
uint32 row_step
uint8[] data
bool is_dense
================================================================================
MSG: std_msgs/Header
builtin_interfaces/Time stamp
string frame_id
================================================================================
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
================================================================================
MSG: sensor_msgs/PointField
uint8 INT8=1
uint8 UINT8=2
uint8 INT16=3
uint8 UINT16=4
uint8 INT32=5
uint8 UINT32=6
uint8 FLOAT32=7
uint8 FLOAT64=8
string name
uint32 offset
uint8 datatype
uint32 count
`;
const STRING = "string data\n";

const VARIANTS = [
  { name: "lz4_float32", compression: "lz4", type: "float32", organized: false },
  { name: "zstd_float64_organized", compression: "zstd", type: "float64", organized: true },
  { name: "zstd_float32_organized", compression: "zstd", type: "float32", organized: true },
  { name: "lz4_float64", compression: "lz4", type: "float64", organized: false },
];
const GRID_WIDTH = 128;

function readXyz(file) {
  return fs
    .readFileSync(file, "utf8")
    .split("\n")
    .filter((l) => l.trim())
    .map((l) => l.trim().split(/\s+/).slice(0, 3).map(Number));
}

// Every fifth pixel of the grid left empty (NaN), as a depth camera leaves holes.
function pixels(n) {
  const out = [];
  for (let i = 0; i < n; ++i) out.push(i + Math.floor(i / 4));
  return out;
}

// x y z, then an intensity the reader must skip; float64 points are padded to 32 bytes.
function layout(type) {
  return type === "float32"
    ? { size: 4, datatype: 7, step: 16, offsets: [0, 4, 8], intensity: 12 }
    : { size: 8, datatype: 8, step: 32, offsets: [0, 8, 16], intensity: 24 };
}

// The cloud as full rows of points: `slots` entries, each a point or null (a hole).
function slotsOf(points, organized) {
  if (!organized) return { width: points.length, height: 1, slots: points };
  const px = pixels(points.length);
  const height = Math.floor(px[px.length - 1] / GRID_WIDTH) + 1;
  const slots = new Array(GRID_WIDTH * height).fill(null);
  px.forEach((p, i) => (slots[p] = points[i]));
  return { width: GRID_WIDTH, height, slots };
}

function pointCloud2(points, variant, stampSec) {
  const l = layout(variant.type);
  const { width, height, slots } = slotsOf(points, variant.organized);
  const data = new Uint8Array(slots.length * l.step);
  const view = new DataView(data.buffer);
  slots.forEach((p, i) => {
    for (let a = 0; a < 3; ++a) {
      const v = p ? p[a] : NaN;
      if (l.size === 4) view.setFloat32(i * l.step + l.offsets[a], v, true);
      else view.setFloat64(i * l.step + l.offsets[a], v, true);
    }
    view.setFloat32(i * l.step + l.intensity, 100 + (i % 7), true);
  });
  return {
    header: { stamp: { sec: stampSec, nanosec: 0 }, frame_id: "camera_depth_optical_frame" },
    height,
    width,
    fields: [
      { name: "x", offset: l.offsets[0], datatype: l.datatype, count: 1 },
      { name: "y", offset: l.offsets[1], datatype: l.datatype, count: 1 },
      { name: "z", offset: l.offsets[2], datatype: l.datatype, count: 1 },
      { name: "intensity", offset: l.intensity, datatype: 7, count: 1 },
    ],
    is_bigendian: false,
    point_step: l.step,
    row_step: l.step * width,
    data,
    is_dense: !variant.organized,
  };
}

function pcdOf(points, variant) {
  const { width, height, slots } = slotsOf(points, variant.organized);
  const size = variant.type === "float32" ? 4 : 8;
  const header =
    `VERSION 0.7\nFIELDS x y z\nSIZE ${size} ${size} ${size}\nTYPE F F F\nCOUNT 1 1 1\n` +
    `WIDTH ${width}\nHEIGHT ${height}\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS ${slots.length}\nDATA binary\n`;
  const body = Buffer.alloc(slots.length * 3 * size);
  slots.forEach((p, i) => {
    for (let a = 0; a < 3; ++a) {
      const v = p ? p[a] : NaN;
      if (size === 4) body.writeFloatLE(v, (i * 3 + a) * 4);
      else body.writeDoubleLE(v, (i * 3 + a) * 8);
    }
  });
  return Buffer.concat([Buffer.from(header, "ascii"), body]);
}

async function main() {
  const [outDir, ...clouds] = process.argv.slice(2);
  if (!outDir || clouds.length === 0) {
    console.error("usage: node write_clouds.js OUT_DIR CLOUD.xyz...");
    process.exit(2);
  }
  fs.mkdirSync(outDir, { recursive: true });
  const { compress } = await compressors();
  const cloudWriter = new MessageWriter(parse(POINTCLOUD2, { ros2: true }));
  const stringWriter = new MessageWriter(parse(STRING, { ros2: true }));
  const points = clouds.map(readXyz);
  for (const variant of VARIANTS) {
    const writable = new BufferWritable();
    const writer = new McapWriter({
      writable,
      useChunks: true,
      useStatistics: true,
      useSummaryOffsets: true,
      useChunkIndex: true,
      useMessageIndex: true,
      chunkSize: 256 * 1024,
      compressChunk: compress[variant.compression],
    });
    await writer.start({ profile: "ros2", library: "cloudshape interop (@mcap/core)" });
    const cloudSchema = await writer.registerSchema({
      name: "sensor_msgs/msg/PointCloud2",
      encoding: "ros2msg",
      data: Buffer.from(POINTCLOUD2),
    });
    const stringSchema = await writer.registerSchema({ name: "std_msgs/msg/String", encoding: "ros2msg", data: Buffer.from(STRING) });
    const camera = await writer.registerChannel({
      topic: "/camera/depth/points",
      schemaId: cloudSchema,
      messageEncoding: "cdr",
      metadata: new Map(),
    });
    const rosout = await writer.registerChannel({ topic: "/rosout", schemaId: stringSchema, messageEncoding: "cdr", metadata: new Map() });
    for (let k = 0; k < points.length; ++k) {
      const t = 1_700_000_000_000_000_000n + BigInt(k) * 200_000_000n;
      const msg = cloudWriter.writeMessage(pointCloud2(points[k], variant, 100 + k));
      await writer.addMessage({ channelId: camera, sequence: k, logTime: t, publishTime: t, data: msg });
      const text = stringWriter.writeMessage({ data: `cloud ${k} recorded` });
      await writer.addMessage({ channelId: rosout, sequence: k, logTime: t + 1n, publishTime: t + 1n, data: text });
      fs.writeFileSync(path.join(outDir, `${variant.name}_${k}.pcd`), pcdOf(points[k], variant));
    }
    await writer.end();
    fs.writeFileSync(path.join(outDir, `${variant.name}.mcap`), writable.bytes());
  }
}

main().catch((e) => {
  console.error(`write_clouds.js: ${e.stack || e}`);
  process.exit(1);
});
