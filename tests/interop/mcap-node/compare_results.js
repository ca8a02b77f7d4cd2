// Compares two files of cloudshape JSON lines object for object, ignoring `source` and
// `timings_ms`: numbers equal within a relative 1e-9 (absolute below 1), everything else exactly.
//   node compare_results.js EXPECTED.jsonl ACTUAL.jsonl
"use strict";
const fs = require("fs");

const TOLERANCE = 1e-9;

function lines(file) {
  return fs
    .readFileSync(file, "utf8")
    .split("\n")
    .filter((l) => l.trim())
    .map((l) => JSON.parse(l));
}

function differences(a, b, where, out) {
  if (typeof a === "number" && typeof b === "number") {
    if (Math.abs(a - b) > TOLERANCE * Math.max(1, Math.abs(a), Math.abs(b))) out.push(`${where}: ${a} != ${b}`);
    return;
  }
  if (a === null || b === null || typeof a !== "object" || typeof b !== "object") {
    if (a !== b) out.push(`${where}: ${JSON.stringify(a)} != ${JSON.stringify(b)}`);
    return;
  }
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  for (const k of keys) {
    if (where === "" && (k === "source" || k === "timings_ms")) continue;
    if (!(k in a) || !(k in b)) out.push(`${where}.${k}: present on one side only`);
    else differences(a[k], b[k], `${where}.${k}`, out);
  }
}

const [expectedFile, actualFile] = process.argv.slice(2);
const expected = lines(expectedFile);
const actual = lines(actualFile);
const problems = [];
if (expected.length !== actual.length) problems.push(`${expected.length} results expected, ${actual.length} found`);
for (let i = 0; i < Math.min(expected.length, actual.length); ++i) {
  const found = [];
  differences(expected[i], actual[i], "", found);
  if (expected[i].objects.length === 0) found.push("no object recognised: the comparison would prove nothing");
  for (const f of found) problems.push(`${expected[i].source} vs ${actual[i].source}${f}`);
}
if (problems.length) {
  for (const p of problems.slice(0, 20)) console.error(`compare_results.js: ${p}`);
  process.exit(1);
}
console.log(`compare_results.js: ${actual.length} results equal (numbers within ${TOLERANCE} relative)`);
