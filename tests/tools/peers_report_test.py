#!/usr/bin/env python3
"""tools/peers/peers_report.py without PCL or Open3D: the parsers against hand-made outputs of
every tool and, when the binaries are given (CLOUDSHAPE_RECOGNIZE_BIN, CLOUDSHAPE_SYNTH_BIN,
CLOUDSHAPE_BENCH_BIN, CLOUDSHAPE_SHARED_DATA_DIR), against what cloudshape prints today, so a
change of its output format shows here and not in the middle of a benchmark run; then the
medians, ratios, table and JSON against hand-worked figures."""
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent / "tools" / "peers"))
import peers_report as pr  # noqa: E402

RECOGNIZE_LINE = json.dumps({
    "source": "box.pcd", "points_in": 100000, "objects": [{"shape": "box"}],
    "timings_ms": {"preprocess": 20.0, "total": 31.5}})
PCL_LINE = json.dumps({
    "tool": "pcl", "file": "cylinder.pcd", "shape": "cylinder", "planes": 2,
    "fit_found": True, "ms": 240.25})
OPEN3D_LINE = json.dumps({
    "tool": "open3d", "file": "cylinder.pcd", "shape": "cylinder", "planes": 2,
    "fit_found": False, "ms": 180.0})
BENCH_SCENES = json.dumps({"rows": [], "scenes": [
    {"file": "learn0.pcd", "total_ms": 100.0, "wall_ms": 101.0,
     "objects": [{"outcome": "right"}, {"outcome": "missed"}]},
    {"file": "learn1.pcd", "total_ms": 80.0, "objects": []}]}, indent=2)
LCCP_LINES = "\n".join(json.dumps({
    "tool": "pcl_lccp", "file": f, "segments": 3, "ms": ms,
    "stages_ms": {"table": 30.0, "supervoxels": sv, "lccp": 2.0}})
    for f, ms, sv in (("learn0.pcd", 50.0, 15.0), ("learn1.pcd", 40.0, 6.0)))


def tsv(samples):
    return ["\t".join(str(x) for x in s) + "\n" for s in samples]


class RecordTest(unittest.TestCase):
    def test_cloudshape_shape_takes_its_own_total(self):
        self.assertEqual(pr.record("shape", "cloudshape", "box", "noise\n" + RECOGNIZE_LINE),
                         [("shape", "box", "cloudshape", 31.5, "box")])

    def test_peers_take_ms_and_say_what_they_fitted(self):
        self.assertEqual(pr.record("shape", "pcl", None, PCL_LINE),
                         [("shape", "cylinder", "pcl", 240.25, "2 planes + cylinder fit")])
        self.assertEqual(pr.record("shape", "open3d", "cylinder", OPEN3D_LINE)[0][3:],
                         (180.0, "2 planes"))

    def test_bench_scenes_give_one_sample_per_frame(self):
        self.assertEqual(pr.record("scene", "cloudshape", None, BENCH_SCENES), [
            ("scene", "learn0.pcd", "cloudshape", 100.0, "1/2 objects right"),
            ("scene", "learn1.pcd", "cloudshape", 80.0, "0/0 objects right")])

    def test_lccp_gives_its_total_and_supervoxels_plus_lccp_alone(self):
        got = pr.record("scene", "pcl_lccp", None, LCCP_LINES)
        self.assertEqual([(s[1], s[2], s[3]) for s in got], [
            ("learn0.pcd", "pcl_lccp", 50.0), ("learn0.pcd", "pcl_lccp_only", 17.0),
            ("learn1.pcd", "pcl_lccp", 40.0), ("learn1.pcd", "pcl_lccp_only", 8.0)])

    def test_no_output_or_unknown_tool_is_an_error(self):
        with self.assertRaises(ValueError):
            pr.record("shape", "pcl", "box", "pcl-shapes: cannot read box.pcd\n")
        with self.assertRaises(ValueError):
            pr.record("shape", "cgal", "box", PCL_LINE)


class RealOutputTest(unittest.TestCase):
    """The parsers against the binaries of this build, where the test is given them."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_cloudshape_recognize(self):
        synth = os.environ.get("CLOUDSHAPE_SYNTH_BIN")
        recognize = os.environ.get("CLOUDSHAPE_RECOGNIZE_BIN")
        if not synth or not recognize:
            self.skipTest("CLOUDSHAPE_SYNTH_BIN / CLOUDSHAPE_RECOGNIZE_BIN not set")
        cloud = self.dir / "box.pcd"
        subprocess.run([synth, "shape", "--shape", "box", "--dims", "3,2,1", "--points", "3000",
                        "--seed", "2", "--noise", "0.005", "-o", str(cloud)],
                       check=True, capture_output=True)
        out = subprocess.run([recognize, str(cloud)], check=True, capture_output=True, text=True)
        (sample,) = pr.record("shape", "cloudshape", "box", out.stdout)
        self.assertEqual(sample[:3], ("shape", "box", "cloudshape"))
        self.assertGreater(sample[3], 0.0)
        self.assertEqual(sample[4], "box")

    def test_cloudshape_bench_scenes(self):
        bench = os.environ.get("CLOUDSHAPE_BENCH_BIN")
        shared = os.environ.get("CLOUDSHAPE_SHARED_DATA_DIR", "")
        frame = pathlib.Path(shared) / "real" / "mosd_learn" / "learn0.pcd"
        if not bench or not frame.is_file():
            self.skipTest("CLOUDSHAPE_BENCH_BIN not set or no mosd_learn/learn0.pcd")
        (self.dir / "learn0.pcd").symlink_to(frame)
        out = subprocess.run([bench, "--scenes", str(self.dir), "--json"], check=True,
                             capture_output=True, text=True)
        (sample,) = pr.record("scene", "cloudshape", None, out.stdout)
        self.assertEqual(sample[:3], ("scene", "learn0.pcd", "cloudshape"))
        self.assertGreater(sample[3], 0.0)


class ReportTest(unittest.TestCase):
    def samples(self):
        lines = []
        for ms in (30.0, 10.0, 20.0):
            lines += tsv([("shape", "cylinder", "cloudshape", ms, "cylinder")])
        for ms in (200.0, 400.0, 300.0):
            lines += tsv([("shape", "cylinder", "pcl", ms, "2 planes + cylinder fit")])
        for ms in (100.0, 120.0, 500.0):
            lines += tsv([("shape", "cylinder", "open3d", ms, "2 planes")])
        lines += tsv([("shape", "box", "cloudshape", 12.0, "box"),
                      ("shape", "box", "pcl", 60.0, "6 planes")])
        # Two frames, two repetitions: per-frame medians 95 and 70, then their median 82.5.
        for frame, ours, lccp, alone in (("learn0.pcd", (90.0, 100.0), (50.0, 70.0), (10.0, 30.0)),
                                         ("learn1.pcd", (60.0, 80.0), (40.0, 40.0), (5.0, 5.0))):
            for i in range(2):
                lines += tsv([("scene", frame, "cloudshape", ours[i], "2/2 objects right"),
                              ("scene", frame, "pcl_lccp", lccp[i], "3 segments"),
                              ("scene", frame, "pcl_lccp_only", alone[i], "3 segments")])
        return lines

    def test_medians_fastest_peer_and_ratio(self):
        times, answers = pr.read_samples(self.samples())
        rows = {r["case"]: r for r in pr.shape_rows(times, answers)}
        cyl = rows["cylinder"]
        self.assertEqual(cyl["median_ms"], {"cloudshape": 20.0, "pcl": 300.0, "open3d": 120.0})
        self.assertEqual(cyl["fastest_peer"], "open3d")
        self.assertAlmostEqual(cyl["ratio"], 20.0 / 120.0)
        self.assertTrue(cyl["open3d_planes_only"])
        self.assertEqual(cyl["answers"]["pcl"], "2 planes + cylinder fit")
        self.assertEqual(rows["box"]["fastest_peer"], "pcl")
        self.assertAlmostEqual(rows["box"]["ratio"], 0.2)
        self.assertFalse(rows["box"]["open3d_planes_only"])

    def test_scene_row_is_the_median_of_per_frame_medians(self):
        times, answers = pr.read_samples(self.samples())
        scene = pr.scene_row(times, answers)
        self.assertEqual(scene["frames"], 2)
        self.assertEqual(scene["median_ms"],
                         {"cloudshape": 82.5, "pcl_lccp": 50.0, "pcl_lccp_only": 12.5})
        self.assertAlmostEqual(scene["ratio"], 82.5 / 50.0)
        self.assertAlmostEqual(scene["ratio_lccp_only"], 82.5 / 12.5)

    def test_table_and_json_through_the_command_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            samples = pathlib.Path(tmp) / "samples.tsv"
            samples.write_text("".join(self.samples()), encoding="utf-8")
            out = pathlib.Path(tmp) / "peers.json"
            table = subprocess.run(
                [sys.executable, str(HERE.parent.parent / "tools" / "peers" / "peers_report.py"),
                 "report", str(samples), "--json", str(out), "--meta", "pcl=1.13.0",
                 "--meta", "open3d=0.16.1", "--meta", "load average before=1.5 1.0 0.5"],
                check=True, capture_output=True, text=True).stdout
            data = json.loads(out.read_text(encoding="utf-8"))
        self.assertIn("| cloudshape (ms) | PCL 1.13.0 (ms) | Open3D 0.16.1 (ms) |", table)
        self.assertIn("| cylinder, 100k noisy points | 20.0 | 300.0 | 120.0 (planes only: no "
                      "cylinder fit) | open3d | **0.167** (6.0x faster) |", table)
        self.assertIn("| box, 100k noisy points | 12.0 | 60.0 | n/a | pcl | **0.200** (5.0x "
                      "faster) |", table)
        self.assertIn("| 82.5 (whole recognition) | 50.0 (LCCP; 12.5 without the table plane) "
                      "| not run (no LCCP) | pcl | **1.650** (1.6x slower); against LCCP alone "
                      "**6.600** (6.6x slower) |", table)
        self.assertIn("load average before 1.5 1.0 0.5", table)
        self.assertEqual([r["case"] for r in data["shapes"]], ["cylinder", "box"])
        self.assertEqual(data["shapes"][0]["samples_ms"]["pcl"], [200.0, 400.0, 300.0])
        self.assertEqual(data["scene"]["frames"], 2)
        self.assertEqual(data["meta"]["pcl"], "1.13.0")


if __name__ == "__main__":
    unittest.main()
