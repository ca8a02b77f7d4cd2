// Checks a recording written by cloudshape (recognize --record, echo --record) with the libraries
// behind Foxglove: @mcap/core reads and validates it, every message is decoded by
// @foxglove/rosmsg2-serialization from the schema text the file itself carries, and the values
// agree with cloudshape's JSON lines for the same clouds.
//   node check_recording.js RECORDING.mcap RESULTS.jsonl [--clouds] [--stamps SEC,SEC,...]
// --clouds: a PointCloud2 per result is expected too; --stamps: the header stamp (whole seconds)
// each result must carry, in order (the input clouds' own stamps).
"use strict";
const fs = require("fs");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");
const { compressors, readValidated, fail } = require("./mcap_files");

const LENGTH = 1e-9; // relative, on lengths and positions printed by the same program
const DIRECTION = 1e-9; // on unit vectors

function near(a, b, tol, what) {
  if (!(Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b)))) fail(`${what}: ${a} != ${b}`);
}
function nearVec(a, b, tol, what) {
  a.forEach((v, i) => near(v, b[i], tol, `${what}[${i}]`));
}
// The image of unit vector e_k under the rotation of quaternion q.
function rotated(q, k) {
  const { x, y, z, w } = q;
  const m = [
    [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
    [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
    [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
  ];
  return [m[0][k], m[1][k], m[2][k]];
}
const xyz = (p) => [p.x, p.y, p.z];

// The solid's own box as Detection3D.bbox.size: along axes[0], axes[1], axes[2].
function expectedSize(object) {
  const d = object.dimensions;
  switch (object.shape) {
    case "box": return [d.length, d.width, d.height];
    case "sphere": return [2 * d.radius, 2 * d.radius, 2 * d.radius];
    case "cylinder":
    case "cone": return [d.height, 2 * d.radius, 2 * d.radius];
    default: return undefined;
  }
}
const MARKER_TYPE = { box: 1, sphere: 2, cylinder: 3, cone: 11, tetrahedron: 11, pentagonal_prism: 11, prism: 11 };

function checkDetections(msg, result, where) {
  if (msg.detections.length !== result.objects.length) {
    fail(`${where}: ${msg.detections.length} detections, ${result.objects.length} objects in the JSON`);
  }
  msg.detections.forEach((det, i) => {
    const object = result.objects[i];
    const w = `${where} detection ${i}`;
    const hyp = det.results[0] || fail(`${w}: no hypothesis`);
    if (hyp.hypothesis.class_id !== object.shape) fail(`${w}: class_id ${hyp.hypothesis.class_id}, shape ${object.shape}`);
    near(hyp.hypothesis.score, object.confidence, 1e-12, `${w} score`);
    nearVec(xyz(hyp.pose.pose.position), object.pose.center, LENGTH, `${w} position`);
    if (hyp.pose.covariance.length !== 36) fail(`${w}: covariance of ${hyp.pose.covariance.length}`);
    const q = hyp.pose.pose.orientation;
    near(Math.hypot(q.x, q.y, q.z, q.w), 1, 1e-12, `${w} |quaternion|`);
    nearVec(rotated(q, 0), object.pose.axes[0], DIRECTION, `${w} x axis`);
    nearVec(rotated(q, 1), object.pose.axes[1], DIRECTION, `${w} y axis`);
    const size = expectedSize(object);
    if (size) nearVec(xyz(det.bbox.size), size, LENGTH, `${w} bbox size`);
    if (det.header.stamp.sec !== msg.header.stamp.sec) fail(`${w}: header differs from the array's`);
  });
}

// markers[0] clears the namespace; then per object its solid (for an unknown object the
// LINE_LIST of its extent's edges, none when it has no extent) and its text label.
function checkMarkers(msg, result, header, where) {
  const m = msg.markers;
  if (m[0].action !== 3) fail(`${where}: the first marker is not a DELETEALL`);
  let next = 1;
  result.objects.forEach((object, i) => {
    const w = `${where} object ${i}`;
    const unknown = object.shape === "unknown";
    const extent = object.extent && Math.max(...object.extent.size) > 0;
    const solid = unknown && !extent ? undefined : m[next++];
    const label = m[next++] || fail(`${w}: no label marker`);
    if (solid && unknown && solid.type !== 5) fail(`${w}: marker type ${solid.type} for an unknown object's extent`);
    if (solid) {
      if (solid.ns !== result.source) fail(`${w}: namespace ${solid.ns}, source ${result.source}`);
      if (MARKER_TYPE[object.shape] !== undefined && solid.type !== MARKER_TYPE[object.shape]) {
        fail(`${w}: marker type ${solid.type} for a ${object.shape}`);
      }
      if (object.shape === "box") nearVec(xyz(solid.scale), expectedSize(object), LENGTH, `${w} cube scale`);
      if (object.shape === "sphere") nearVec(xyz(solid.scale), expectedSize(object), LENGTH, `${w} sphere scale`);
      if (object.shape === "cylinder") {
        const d = object.dimensions;
        nearVec(xyz(solid.scale), [2 * d.radius, 2 * d.radius, d.height], LENGTH, `${w} cylinder scale`);
      }
    }
    const shown = (object.partial ? "partial " : "") + object.shape;
    if (label.type !== 9 || !label.text.startsWith(shown)) fail(`${w}: label ${label.type} '${label.text}'`);
    for (const marker of solid ? [solid, label] : [label]) {
      if (marker.header.stamp.sec !== header.stamp.sec || marker.header.frame_id !== header.frame_id) {
        fail(`${w}: marker header differs from the detections'`);
      }
    }
  });
  if (next !== m.length) fail(`${where}: ${m.length} markers, ${next} expected for ${result.objects.length} objects`);
}

function checkCloud(msg, result, where) {
  const names = msg.fields.map((f) => f.name);
  for (const axis of ["x", "y", "z"]) if (!names.includes(axis)) fail(`${where}: no field ${axis}`);
  const field = (n) => msg.fields.find((f) => f.name === n);
  const view = new DataView(msg.data.buffer, msg.data.byteOffset, msg.data.byteLength);
  const read = (f, at) => (f.datatype === 7 ? view.getFloat32(at, !msg.is_bigendian) : view.getFloat64(at, !msg.is_bigendian));
  let finite = 0;
  for (let r = 0; r < msg.height; ++r) {
    for (let c = 0; c < msg.width; ++c) {
      const at = r * msg.row_step + c * msg.point_step;
      if (["x", "y", "z"].every((n) => Number.isFinite(read(field(n), at + field(n).offset)))) ++finite;
    }
  }
  if (finite !== result.points_in) fail(`${where}: ${finite} finite points, points_in ${result.points_in}`);
}

async function main() {
  const args = process.argv.slice(2);
  const [file, resultsFile] = args;
  const clouds = args.includes("--clouds");
  const stampsAt = args.indexOf("--stamps");
  const stamps = stampsAt >= 0 ? args[stampsAt + 1].split(",").map(Number) : undefined;
  const results = fs.readFileSync(resultsFile, "utf8").split("\n").filter((l) => l.trim()).map((l) => JSON.parse(l));
  const { decompressHandlers } = await compressors();
  const { header, indexed, messages } = await readValidated(file, decompressHandlers);
  if (header.profile !== "ros2") fail(`${file}: profile '${header.profile}', not ros2`);

  const readers = new Map();
  const byType = { "vision_msgs/msg/Detection3DArray": [], "visualization_msgs/msg/MarkerArray": [], "sensor_msgs/msg/PointCloud2": [] };
  for (const message of messages) {
    const channel = indexed.channelsById.get(message.channelId);
    const schema = indexed.schemasById.get(channel.schemaId);
    if (channel.messageEncoding !== "cdr" || schema.encoding !== "ros2msg") {
      fail(`${file}: channel ${channel.topic} is ${channel.messageEncoding} / ${schema.encoding}`);
    }
    if (!readers.has(schema.id)) {
      readers.set(schema.id, new MessageReader(parse(new TextDecoder().decode(schema.data), { ros2: true })));
    }
    const reader = readers.get(schema.id);
    const decoded = reader.readMessage(message.data);
    if (reader.lastReadHadTrailingBytes()) fail(`${file}: a ${schema.name} message is longer than its schema says`);
    (byType[schema.name] || fail(`${file}: unexpected schema ${schema.name}`)).push(decoded);
  }
  const detections = byType["vision_msgs/msg/Detection3DArray"];
  const markers = byType["visualization_msgs/msg/MarkerArray"];
  const cloudMsgs = byType["sensor_msgs/msg/PointCloud2"];
  if (detections.length !== results.length || markers.length !== results.length) {
    fail(`${file}: ${detections.length} Detection3DArray and ${markers.length} MarkerArray for ${results.length} results`);
  }
  if (clouds ? cloudMsgs.length !== results.length : cloudMsgs.length !== 0) {
    fail(`${file}: ${cloudMsgs.length} PointCloud2 messages for ${results.length} results`);
  }
  let objects = 0;
  results.forEach((result, i) => {
    const where = `${file} result ${i} (${result.source})`;
    if (stamps && detections[i].header.stamp.sec !== stamps[i]) fail(`${where}: stamp ${detections[i].header.stamp.sec}, input ${stamps[i]}`);
    checkDetections(detections[i], result, where);
    checkMarkers(markers[i], result, detections[i].header, where);
    if (clouds) {
      checkCloud(cloudMsgs[i], result, where);
      const cloudHeader = cloudMsgs[i].header, resultHeader = detections[i].header;
      if (cloudHeader.stamp.sec !== resultHeader.stamp.sec || cloudHeader.stamp.nanosec !== resultHeader.stamp.nanosec ||
          cloudHeader.frame_id !== resultHeader.frame_id) {
        fail(`${where}: the cloud's header differs from the result's (a player would not overlay them)`);
      }
    }
    objects += result.objects.length;
  });
  console.log(
    `check_recording.js: ${file}: valid (${indexed.chunkIndexes.length} chunks, ${messages.length} messages, ` +
      `summary and statistics agree); ${results.length} results, ${objects} objects decoded and equal to the JSON`,
  );
}

main().catch((e) => {
  console.error(`check_recording.js: ${e.message || e}`);
  process.exit(1);
});
