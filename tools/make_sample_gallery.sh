#!/usr/bin/env bash
# Renders one screenshot per sample of impetus-samples into docs/images/samples/ for
# docs/samples.md's gallery: headless (SDL's offscreen driver, Mesa's llvmpipe), 800 x 450, the
# sample's panel included. Each sample runs long enough to show what it is about (FRAMES below,
# 1/60 s each; 240 unless listed). Deterministic: the same build gives the same pictures.
#
#   tools/make_sample_gallery.sh [path/to/impetus-samples]
#
# The default app is the release build's (./run build makes it). File names: the sample's
# "Category/Name" in lower case with spaces and slashes as underscores (engine_joint_grid.png).
set -euo pipefail
cd "$(dirname "$0")/.."

app="${1:-build/release/apps/samples/impetus-samples}"
if [ ! -x "$app" ]; then
  echo "make_sample_gallery: no impetus-samples at '$app' (./run build, or pass its path)" >&2
  exit 2
fi
out=docs/images/samples
mkdir -p "$out"

# Frames per sample where 4 s is not the telling moment.
declare -A FRAMES=(
  ["Book/Hovercraft"]=1500   # 25 s: the slalom's first turn and its sideslip
  ["Book/Bumper cars"]=60    # 1 s: just after the crash (0.65 s)
  ["Book/Cannon"]=420        # 7 s: the shell on its way down to the target
  ["Book/Cannon2"]=420
  ["Book/Explosion"]=150
  ["Book/Particles"]=900     # 15 s: piles on the obstacles, drift in the wind
  ["Engine/Smash"]=60        # 1 s: the projectile inside the block
  ["Engine/Conveyor and platform"]=900  # 15 s: boxes landed on the one-way platform
  ["Engine/Tumbler"]=600
  ["Engine/Ragdoll rain"]=600  # 10 s: the first columns landed, more on their way
)

count=0
while IFS=$'\t' read -r name _; do
  frames="${FRAMES[$name]:-240}"
  file="$out/$(echo "$name" | tr '[:upper:]' '[:lower:]' | tr ' /' '__').png"
  "$app" --sample "$name" --frames "$frames" --width 800 --height 450 --screenshot "$file" >/dev/null
  echo "$file  ($name, $frames frames)"
  count=$((count + 1))
done < <("$app" --list)
echo "make_sample_gallery: $count pictures in $out"
