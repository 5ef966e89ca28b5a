#!/bin/sh
# Writes every real dataset of the benchmarks into one folder (default build/data):
# Natural Earth and US counties from the npm devDependencies, and three GSHHG regions (Europe,
# Asia, the eastern hemisphere) if gmt is installed.
# Usage: scripts/datasets/all.sh [output folder]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out_dir=${1:-"$here/../../build/data"}
node "$here/natural_earth.mjs" "$out_dir"
if command -v gmt >/dev/null; then
  "$here/gshhg_region.sh" "$out_dir"
  "$here/gshhg_region.sh" "$out_dir" 60/130/-10/50 gshhg_asia.gpl
  "$here/gshhg_region.sh" "$out_dir" 0/180/-90/90 gshhg_east.gpl
else
  echo "gmt not installed: no GSHHG region (apt-get install gmt gmt-gshhg-full)" >&2
fi
