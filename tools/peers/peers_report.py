#!/usr/bin/env python3
"""The parsing and the tables of tools/bench_peers.sh (standard library only, so it is tested
without PCL or Open3D: tests/tools/peers_report_test.py).

  peers_report.py record KIND TOOL [CASE] < OUTPUT >> SAMPLES
      KIND shape: OUTPUT is cloudshape-recognize's JSON lines (TOOL cloudshape: timings_ms.total)
      or a peer's one JSON line (pcl, open3d: "ms"); CASE names the shape.
      KIND scene: OUTPUT is `cloudshape-bench --scenes --json` (TOOL cloudshape: each frame's
      total_ms) or pcl-lccp's JSON lines (TOOL pcl_lccp: "ms", and its supervoxels + LCCP
      stages alone as pcl_lccp_only); the case is the frame's file.
      Appends one tab-separated sample per measurement: kind, case, tool, ms, answer.
  peers_report.py report SAMPLES [--json OUT] [--meta KEY=VALUE]...
      The Markdown table on stdout (medians per shape, per frame; ratio cloudshape / fastest
      peer) and the same figures with every sample as JSON in OUT.
"""
import argparse
import collections
import json
import statistics
import sys

PEERS = ("pcl", "open3d")
# What each tool runs, for the table's legend and the JSON.
PIPELINES = {
    "cloudshape": "whole recognition (cloudshape-recognize's timings_ms.total: preprocessing, "
                  "segmentation, planes, key-points, classification, solver)",
    "pcl": "voxel grid, normals (NormalEstimationOMP), RANSAC planes (SACSegmentation), "
           "SAC cylinder / cone / sphere fit (SACSegmentationFromNormals); told the shape",
    "open3d": "voxel grid, normals, RANSAC planes (segment_plane) only: Open3D has no "
              "cylinder, cone or sphere fit",
    "pcl_lccp": "table plane removed (SACSegmentation), SupervoxelClustering + "
                "LCCPSegmentation with PCL's example parameters; segments only, names no shape",
}
# Open3D stops after its planes on every curved shape: the table says so in the cell.
OPEN3D_NO_FIT = {"cylinder", "cone", "sphere"}


def _json_lines(text):
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("{"):
            yield json.loads(line)


def _stem(name):
    return name.rsplit("/", 1)[-1].rsplit(".", 1)[0]


def _shapes_answer(result):
    return ",".join(o.get("shape", "?") for o in result.get("objects", [])) or "none"


def _peer_answer(line):
    count = line.get("planes", 0)
    planes = f"{count} plane{'' if count == 1 else 's'}"
    if line.get("fit_found") is True:
        return f"{planes} + {line.get('shape')} fit"
    return planes


def record(kind, tool, case, text):
    """Samples (kind, case, tool, ms, answer) from one tool's output."""
    samples = []
    if kind == "shape" and tool == "cloudshape":
        for r in _json_lines(text):
            samples.append((kind, case or _stem(r["source"]), tool,
                            float(r["timings_ms"]["total"]), _shapes_answer(r)))
    elif kind == "shape" and tool in PEERS:
        for r in _json_lines(text):
            samples.append((kind, case or _stem(r["file"]), tool, float(r["ms"]),
                            _peer_answer(r)))
    elif kind == "scene" and tool == "cloudshape":
        for s in json.loads(text)["scenes"]:
            right = sum(1 for o in s.get("objects", []) if o.get("outcome") == "right")
            samples.append((kind, s["file"], tool, float(s["total_ms"]),
                            f"{right}/{len(s.get('objects', []))} objects right"))
    elif kind == "scene" and tool == "pcl_lccp":
        for r in _json_lines(text):
            answer = f"{r.get('segments', 0)} segments"
            samples.append((kind, r["file"], tool, float(r["ms"]), answer))
            stages = r.get("stages_ms", {})
            samples.append((kind, r["file"], "pcl_lccp_only",
                            float(stages["supervoxels"]) + float(stages["lccp"]), answer))
    else:
        raise ValueError(f"no parser for kind {kind!r} and tool {tool!r}")
    if not samples:
        raise ValueError(f"{tool} printed no {kind} result")
    return samples


def read_samples(lines):
    """{kind: {case: {tool: [ms...]}}} and the most frequent answer per (kind, case, tool)."""
    times = collections.defaultdict(lambda: collections.defaultdict(dict))
    answers = collections.defaultdict(collections.Counter)
    for line in lines:
        if not line.strip():
            continue
        kind, case, tool, ms, *rest = line.rstrip("\n").split("\t")
        times[kind][case].setdefault(tool, []).append(float(ms))
        answers[(kind, case, tool)][rest[0] if rest else ""] += 1
    top = {key: counter.most_common(1)[0][0] for key, counter in answers.items()}
    return times, top


def _ratio(ours, theirs):
    return ours / theirs if ours is not None and theirs else None


def shape_rows(times, answers):
    rows = []
    for case, tools in times.get("shape", {}).items():
        medians = {tool: statistics.median(v) for tool, v in tools.items()}
        peers = {t: medians[t] for t in PEERS if t in medians}
        fastest = min(peers, key=peers.get) if peers else None
        ours = medians.get("cloudshape")
        rows.append({
            "case": case,
            "median_ms": medians,
            "fastest_peer": fastest,
            "ratio": _ratio(ours, peers.get(fastest)),
            "open3d_planes_only": case in OPEN3D_NO_FIT,
            "answers": {t: answers.get(("shape", case, t), "") for t in tools},
            "samples_ms": dict(tools),
        })
    return rows


def scene_row(times, answers):
    frames = times.get("scene", {})
    if not frames:
        return None
    per_tool = collections.defaultdict(list)  # each frame's median over the repetitions
    for tools in frames.values():
        for tool, values in tools.items():
            per_tool[tool].append(statistics.median(values))
    medians = {tool: statistics.median(v) for tool, v in per_tool.items()}
    ours = medians.get("cloudshape")
    return {
        "frames": len(frames),
        "median_ms": medians,
        "ratio": _ratio(ours, medians.get("pcl_lccp")),
        "ratio_lccp_only": _ratio(ours, medians.get("pcl_lccp_only")),
        "frame_medians_ms": {case: {t: statistics.median(v) for t, v in tools.items()}
                             for case, tools in frames.items()},
        "answers": {case: {t: answers.get(("scene", case, t), "") for t in tools}
                    for case, tools in frames.items()},
    }


def _points_text(points):
    return f"{int(points) // 1000}k" if points.isdigit() and int(points) % 1000 == 0 else points


def _ms(value):
    return "n/a" if value is None else f"{value:.1f}"


def _ratio_text(ratio):
    if ratio is None:
        return "n/a"
    faster = f"{1 / ratio:.1f}x faster" if ratio < 1 else f"{ratio:.1f}x slower"
    return f"**{ratio:.3f}** ({faster})"


def markdown(shapes, scene, meta):
    pcl = meta.get("pcl", "")
    o3d = meta.get("open3d", "")
    points = _points_text(meta.get("points", "100000"))
    scenes = meta.get("scenes", "mosd_learn")
    out = [
        f"| cloud | cloudshape (ms) | PCL {pcl} (ms) | Open3D {o3d} (ms) | fastest peer "
        "| cloudshape / fastest peer |",
        "|---|---:|---:|---:|---|---:|",
    ]
    for row in shapes:
        m = row["median_ms"]
        o3d_cell = _ms(m.get("open3d"))
        if row["open3d_planes_only"] and "open3d" in m:
            o3d_cell += f" (planes only: no {row['case']} fit)"
        out.append(f"| {row['case']}, {points} noisy points | {_ms(m.get('cloudshape'))} "
                   f"| {_ms(m.get('pcl'))} | {o3d_cell} | {row['fastest_peer'] or 'n/a'} "
                   f"| {_ratio_text(row['ratio'])} |")
    if scene:
        m = scene["median_ms"]
        out.append(
            f"| scene: {scenes}, {scene['frames']} Kinect frames (median per frame) "
            f"| {_ms(m.get('cloudshape'))} (whole recognition) "
            f"| {_ms(m.get('pcl_lccp'))} (LCCP; {_ms(m.get('pcl_lccp_only'))} without the "
            f"table plane) | not run (no LCCP) | pcl | {_ratio_text(scene['ratio'])}; "
            f"against LCCP alone {_ratio_text(scene['ratio_lccp_only'])} |")
    out.append("")
    out.append("Milliseconds are medians, timed inside each program around its pipeline "
               "(not process start or file reading). Pipelines:")
    for tool, text in PIPELINES.items():
        out.append(f"- {tool}: {text}.")
    facts = [f"{k} {v}" for k, v in meta.items() if k not in ("pcl", "open3d", "scenes")]
    if facts:
        out.append("")
        out.append("Run: " + "; ".join(facts) + ".")
    return "\n".join(out) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    rec = sub.add_parser("record")
    rec.add_argument("kind", choices=("shape", "scene"))
    rec.add_argument("tool")
    rec.add_argument("case", nargs="?")
    rep = sub.add_parser("report")
    rep.add_argument("samples")
    rep.add_argument("--json")
    rep.add_argument("--meta", action="append", default=[], metavar="KEY=VALUE")
    args = parser.parse_args(argv)

    if args.command == "record":
        try:
            samples = record(args.kind, args.tool, args.case, sys.stdin.read())
        except (ValueError, KeyError, json.JSONDecodeError) as err:
            print(f"peers_report.py record: {err}", file=sys.stderr)
            return 1
        for s in samples:
            print("\t".join(str(x) for x in s))
        return 0

    with open(args.samples, encoding="utf-8") as f:
        times, answers = read_samples(f)
    meta = dict(kv.split("=", 1) for kv in args.meta)
    shapes = shape_rows(times, answers)
    scene = scene_row(times, answers)
    sys.stdout.write(markdown(shapes, scene, meta))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"meta": meta, "pipelines": PIPELINES, "shapes": shapes, "scene": scene},
                      f, indent=2)
            f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
