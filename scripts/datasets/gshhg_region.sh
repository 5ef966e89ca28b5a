#!/bin/sh
# Writes a ~2M-point real dataset with crossings: the GSHHG full-resolution shorelines,
# rivers and national borders of one region, as one .gpl file of lon/lat polylines.
# Rivers cross borders and end on shorelines, so the constraints cross and touch.
# Needs Debian packages gmt and gmt-gshhg-full.
# Usage: scripts/datasets/gshhg_region.sh [output folder, default build/data] [region] [file]
# region is west/east/south/north in degrees; file defaults to gshhg_region.gpl. The default
# region, western and central Europe (-12/45/33/68), gives 2.0M points and 4,268 crossings;
# South, Southeast and East Asia (60/130/-10/50, gshhg_asia.gpl: all.sh makes both) gives
# 2.06M points and 14,897 crossings.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out_dir=${1:-"$here/../../build/data"}
region=${2:-"-12/45/33/68"}
file=${3:-gshhg_region.gpl}
if ! command -v gmt >/dev/null; then
  echo "gmt is missing: apt-get install gmt gmt-gshhg-full" >&2
  exit 1
fi
mkdir -p "$out_dir"
out="$(cd "$out_dir" && pwd)/$file"
# gmt leaves a gmt.history file in its working folder: give it a scratch one.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
# coast -M dumps one feature kind per run: shorelines (-W), all rivers (-Ia), all borders (-Na).
{
  gmt coast -R"$region" -Df -W -M
  gmt coast -R"$region" -Df -Ia -M
  gmt coast -R"$region" -Df -Na -M
} | node "$here/gmt_text_to_gpl.mjs" "$out"
echo "region $region"
