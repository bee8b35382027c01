#!/usr/bin/env bash
# Plots the residual histories of the wedge-in-notch test (dissertation
# 6.5, Figs. 31-35) with gnuplot: |R| over the total Newton iteration, area
# integration against point collocation, one panel per penalty factor.
#
#   contrib/plot_wedge_in_notch.sh [histories.csv] [out.png]
#
# Defaults: the CSV the test writes in the build tree, and
# doc/figures/wedge_in_notch.png.
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
csv=${1:-"$root_dir/build/tests/contact/wedge_in_notch.release/wedge_in_notch_histories.csv"}
png=${2:-"$root_dir/doc/figures/wedge_in_notch.png"}
if [ ! -f "$csv" ]; then
  echo "plot_wedge_in_notch.sh: error: no histories file '$csv' (run: cd build && ctest -R wedge_in_notch)" >&2
  exit 1
fi
command -v gnuplot > /dev/null || { echo "plot_wedge_in_notch.sh: error: gnuplot is missing (contrib/setup.sh installs it)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# one file per (eps, method): total iteration, |R|; the first iterate of
# each increment (the previous equilibrium before the boundary moves) is
# left out
awk -F, -v dir="$tmp" 'NR > 1 && $6 > 0 { m = ($2 == "area integration") ? "area" : "collocation";
  print $3, $7 > (dir "/" $1 "-" m ".dat") }' "$csv"
gnuplot <<GP
set terminal pngcairo size 1200,900 font ",11"
set output "$png"
set multiplot layout 2,2 title "Wedge in notch (dissertation 6.5): residual per Newton iteration"
set logscale y
set format y "10^{%L}"
set xlabel "Newton iteration (all increments)"
set ylabel "|R| (free DoFs)"
set key top right
do for [eps in "10 1e2 1e3 1e4"] {
  set title sprintf("eps_p = %s", eps)
  plot "$tmp/".eps."-area.dat" using 1:2 with lines lw 2 title "area integration", \
       "$tmp/".eps."-collocation.dat" using 1:2 with lines lw 1 title "point collocation"
}
unset multiplot
GP
echo "wrote $png"
