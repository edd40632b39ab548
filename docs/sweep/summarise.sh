#!/usr/bin/env bash
# Prints, for each committed sweep, the Cortex-M7 Pareto front and the default configuration
# as one compact Markdown table (what docs/speed-accuracy.md quotes).
#   docs/sweep/summarise.sh [SCENE...]     (default: the four shared scenes)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(slide_projector spot_shadow three_projectors horizon)
for scene in "${scenes[@]}"; do
  csv=$here/$scene/sweep.csv
  echo "#### $scene"
  echo
  echo "| configuration | M7 instr/frame | M7 /px | M0+ instr/frame | M0+ /px | PSNR dB | RMS vs authored LSB | max LSB | worst texel err |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  # Front rows by M7 cost, then the default (marked) if it is not on the front.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    {
      front = $col["front_m7"] == 1; def = $col["is_default"] == 1
      if (!front && !def) next
      name = $col["label"] (def ? " **(default)**" : "")
      m7 = $col["m7_instructions"]; m0 = $col["m0plus_instructions"]
      printf "%s|| %s | %.2f M | %s | %.2f M | %s | %s | %s | %s | %s |\n", (front ? m7 : 1e12), name, m7 / 1e6,
        $col["m7_per_covered_pixel"], m0 / 1e6, $col["m0plus_per_covered_pixel"], $col["psnr_db"],
        $col["rms_vs_scene_lsb"], $col["max_lsb"], $col["texcoord_err_max_texels"]
    }' "$csv" | sort -t'|' -k1,1 -g | sed 's/^[^|]*||/|/'
  echo
done
