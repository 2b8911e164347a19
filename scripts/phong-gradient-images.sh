#!/usr/bin/env bash
# Renders the default bunny under a strong bend (assets/scripts/bunny_bend.json) with both
# node-gradient schemes and writes docs/images/phong-gradients-{average,fit,difference}.png.
# The difference image is the fit render dimmed to grey with every pixel whose colour differs
# between the two renders drawn from red (1 level of 255) to yellow-white (4 levels and more).
# Needs build/bin/sculpt, xvfb-run, ffmpeg and python3 with numpy (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for scheme in average fit; do
  xvfb-run -a build/bin/sculpt --headless --script assets/scripts/bunny_bend.json --frames 180 \
    --no-ui --supersample 2 --gradients "$scheme" --screenshot "$out/phong-gradients-$scheme.png"
  ffmpeg -loglevel error -y -i "$out/phong-gradients-$scheme.png" -f rawvideo -pix_fmt rgb24 \
    "$tmp/$scheme.rgb"
done
size=$(ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=s=x:p=0 \
  "$out/phong-gradients-fit.png")
/usr/bin/env python3 - "$tmp" "$size" <<'PY'
import sys
import numpy as np
folder, size = sys.argv[1], sys.argv[2]
width, height = (int(v) for v in size.split("x"))
def load(name):
    return np.fromfile(f"{folder}/{name}.rgb", np.uint8).reshape(height, width, 3).astype(float)
fit, average = load("fit"), load("average")
difference = np.abs(fit - average).max(axis=2)
changed = difference > 0
print(f"pixels that differ: {changed.sum()} of {difference.size}; by >= 2 levels: "
      f"{(difference >= 2).sum()}, >= 4: {(difference >= 4).sum()}; largest {difference.max():.0f}")
grey = 0.35 * fit.mean(axis=2)
t = np.clip(difference / 4.0, 0.0, 1.0)
heat = np.stack([np.clip(0.5 + 1.5 * t, 0, 1), np.clip(2 * t - 0.5, 0, 1), np.clip(3 * t - 2, 0, 1)], axis=2) * 255
image = np.where(changed[..., None], heat, grey[..., None])
image.astype(np.uint8).tofile(f"{folder}/difference.rgb")
PY
ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgb24 -s "$size" -i "$tmp/difference.rgb" \
  "$out/phong-gradients-difference.png"
echo "wrote $out/phong-gradients-average.png, -fit.png and -difference.png"
