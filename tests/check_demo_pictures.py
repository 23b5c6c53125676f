#!/usr/bin/python3
"""gridcar demo's pictures: drawn by the figure script (axes in metres around the map, so larger
than the map's own pixels), the cost layer shaded where the map has one, the Voronoi diagram in
red. Usage: check_demo_pictures.py GRIDCAR WORKDIR"""
import os
import subprocess
import sys

import matplotlib.image as mpimg
import numpy as np

gridcar, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
# a 10 m x 6 m ROS map (mode: scale): walls round it, a block, a band of rising cost before it
h, w = 120, 200
img = np.full((h, w), 254, np.uint8)
img[0, :] = img[-1, :] = 0
img[:, 0] = img[:, -1] = 0
img[40:80, 90:110] = 0
for i in range(20):
    img[40:80, 70 + i] = 254 - i * 8
with open(os.path.join(work, "costs.pgm"), "wb") as f:
    f.write(b"P5\n%d %d\n255\n" % (w, h) + img.tobytes())
with open(os.path.join(work, "costs.yaml"), "w") as f:
    f.write("image: costs.pgm\nresolution: 0.05\norigin: [-2.0, -1.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: scale\n")
out = os.path.join(work, "demo")
r = subprocess.run([gridcar, "demo", "--map", os.path.join(work, "costs.yaml"), "--out", out],
                   capture_output=True, text=True, timeout=300)
assert r.returncode == 0, r.stderr
assert "[demo] wrote %s/map.png" % out in r.stderr, r.stderr

pic = mpimg.imread(os.path.join(out, "map.png"))[..., :3]
# axes, labels and legend round the map: far more pixels than the map's 200 x 120 cells
assert pic.shape[0] > 2 * h and pic.shape[1] > 2 * w, pic.shape
# the cost layer: orange shades (red high, blue low) in the picture
orange = (pic[..., 0] > 0.85) & (pic[..., 2] < 0.6) & (pic[..., 1] > 0.45) & (pic[..., 1] < 0.8)
assert orange.sum() > 200, "no cost layer drawn in map.png (%d orange pixels)" % orange.sum()
vor = mpimg.imread(os.path.join(out, "voronoi.png"))[..., :3]
red = (vor[..., 0] > 0.75) & (vor[..., 1] < 0.3) & (vor[..., 2] < 0.3)
assert red.sum() > 50, "no Voronoi cells drawn in voronoi.png (%d red pixels)" % red.sum()
print("demo pictures: %dx%d, %d cost-layer pixels, %d Voronoi pixels" % (pic.shape[1], pic.shape[0], orange.sum(),
                                                                       red.sum()))
