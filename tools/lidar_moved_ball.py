#!/usr/bin/python3
"""The real SphereCalib lidar frame with its calibration ball moved, scored through cloudshape-recognize.

Each frame: the frame's own ball (SOURCES.md: centre (1.723, 2.471, 0.009)) taken out; a ball of
0.25-0.35 m on a 2 cm pole (down to z = -1) scanned anew at a random free spot --min-range to
--max-range from the sensor with the frame's own beams (16, every 2 degrees from -15 to 15,
0.19 degrees of azimuth, 1 cm range noise); the real returns it shadows taken out. As the test
LidarBallInRealFrame builds its three frames. A ball is found when the reported object nearest its
centre is a sphere within 5% of its radius and 5 cm of its centre, with no other object within
three radii (issue 10's tolerances). Prints one line per frame and the counts per range band.

  tools/lidar_moved_ball.py [--frames 40] [--seed 7] [--min-range 2] [--max-range 5.5]
                            [--bin build/bin] [--keep DIR]

Needs python3-numpy (Debian). Deterministic for --seed.
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile

import numpy as np

REAL_BALL = np.array([1.723, 2.471, 0.009])
HERE = os.path.dirname(os.path.abspath(__file__))
FRAME = os.path.join(HERE, '..', '..', 'shared', 'data', 'real', 'spherecalib', 'example3_L1_S1_lidar_sphere.xyz')


def scan_ball(centre, radius, rng):
    """The ball's and its pole's returns for the frame's beams, 1 cm range noise."""
    azimuths = np.radians(np.arange(-180.0, 180.0, 0.19))
    out = []
    for elevation in np.radians(np.arange(-15.0, 16.0, 2.0)):
        d = np.stack([np.cos(elevation) * np.cos(azimuths), np.cos(elevation) * np.sin(azimuths),
                      np.full_like(azimuths, np.sin(elevation))], axis=1)
        b = d @ centre
        disc = b * b - (centre @ centre - radius * radius)
        t = np.where((disc > 0) & (b > 0), b - np.sqrt(np.maximum(disc, 0)), np.inf)
        a = d[:, 0] ** 2 + d[:, 1] ** 2
        bb = -2 * (d[:, 0] * centre[0] + d[:, 1] * centre[1])
        cc = centre[0] ** 2 + centre[1] ** 2 - 0.02 ** 2
        disc2 = bb * bb - 4 * a * cc
        t2 = np.where(disc2 > 0, (-bb - np.sqrt(np.maximum(disc2, 0))) / (2 * a), np.inf)
        z2 = t2 * d[:, 2]
        pole = (disc2 > 0) & (t2 > 0) & (z2 < centre[2] - radius) & (z2 > -1.0)
        t = np.where(pole & (t2 < t), t2, t)
        hit = np.isfinite(t)
        ranges = t[hit] + np.array([rng.gauss(0.0, 0.01) for _ in range(int(hit.sum()))])
        out.append(d[hit] * ranges[:, None])
    return np.concatenate(out)


def make_frame(real, rng, min_range, max_range):
    for _ in range(1000):
        radius = rng.uniform(0.25, 0.35)
        distance = rng.uniform(min_range, max_range)
        azimuth = rng.uniform(-math.pi, math.pi)
        centre = np.array([distance * math.cos(azimuth), distance * math.sin(azimuth), rng.uniform(-0.3, 0.3)])
        if np.min(np.linalg.norm(real - centre, axis=1)) > radius + 0.3:
            break
    ball = scan_ball(centre, radius, rng)
    u = real / np.linalg.norm(real, axis=1)[:, None]
    b = u @ centre
    disc = b * b - (centre @ centre - radius * radius)
    shadowed = (disc > 0) & (b > 0) & (np.linalg.norm(real, axis=1) > b)
    return np.concatenate([real[~shadowed], ball]), centre, radius, len(ball)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--frames', type=int, default=40)
    ap.add_argument('--seed', type=int, default=7)
    ap.add_argument('--min-range', type=float, default=2.0)
    ap.add_argument('--max-range', type=float, default=5.5)
    ap.add_argument('--bin', default=os.path.join(HERE, '..', 'build', 'bin'))
    ap.add_argument('--keep', help='write the frames (.xyz) and their truth (.json) here')
    args = ap.parse_args()
    if not os.path.exists(FRAME):
        sys.exit('lidar_moved_ball: the real frame is missing: %s' % FRAME)
    recognize = os.path.join(args.bin, 'cloudshape-recognize')
    if not os.access(recognize, os.X_OK):
        sys.exit('lidar_moved_ball: no cloudshape-recognize in %s (build first)' % args.bin)
    real = np.loadtxt(FRAME)[:, :3]
    real = real[np.linalg.norm(real - REAL_BALL, axis=1) > 0.45]
    rng = random.Random(args.seed)
    folder = args.keep or tempfile.mkdtemp(prefix='lidar_moved_ball_')
    os.makedirs(folder, exist_ok=True)
    bands = [(0.0, 3.5), (3.5, 4.5), (4.5, math.inf)]
    found = [0] * len(bands)
    total = [0] * len(bands)
    for k in range(args.frames):
        points, centre, radius, ball_points = make_frame(real, rng, args.min_range, args.max_range)
        path = os.path.join(folder, 'ball_%d.xyz' % k)
        np.savetxt(path, points, fmt='%.4f')
        with open(path[:-4] + '.json', 'w') as f:
            json.dump({'center': centre.tolist(), 'radius': radius, 'points': ball_points}, f)
        run = subprocess.run([recognize, '--threads', '1', path], capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit('lidar_moved_ball: cloudshape-recognize failed on %s: %s' % (path, run.stderr.strip()))
        objects = json.loads(run.stdout)['objects']
        near = sorted(((math.dist(o['pose']['center'], centre), o) for o in objects), key=lambda x: x[0])
        right = False
        said = 'nothing'
        if near:
            d, o = near[0]
            r = o.get('dimensions', {}).get('radius')
            others = sum(1 for x in near[1:] if x[0] < 3 * radius)
            right = o['shape'] == 'sphere' and r is not None and abs(r - radius) <= 0.05 * radius and d <= 0.05 and others == 0
            said = '%s%s %.3f m off, %d other(s) within 3 radii' % (o['shape'], ' r=%.3f' % r if r else '', d, others)
        distance = float(np.linalg.norm(centre))
        band = next(i for i, (lo, hi) in enumerate(bands) if lo <= distance < hi)
        total[band] += 1
        found[band] += right
        print('ball_%d  %.2f m  r=%.3f  %d points  %s  %s' % (k, distance, radius, ball_points, 'found' if right else 'MISSED', said))
    names = ['under 3.5 m', '3.5-4.5 m', '4.5 m and beyond']
    print('; '.join('%s: %d of %d' % (n, f, t) for n, f, t in zip(names, found, total)) +
          '; all: %d of %d' % (sum(found), sum(total)))


if __name__ == '__main__':
    main()
