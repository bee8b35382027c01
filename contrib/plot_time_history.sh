#!/usr/bin/env bash
# Plots the time history a dynamic run writes (<base>-time.csv) with
# gnuplot: top, the kinetic energy, the energy the damping dissipated and
# the balance E + D (constant up to the scheme's error); bottom, the penalty
# energy of each contact pair and obstacle (when and where bodies touch).
#
#   contrib/plot_time_history.sh output/falling_rods-time.csv [out.png]
#
# Default output: the CSV's name with .png.
set -euo pipefail
if [ $# -lt 1 ] || [ ! -f "$1" ]; then
  echo "plot_time_history.sh: error: give the time history of a dynamic run (<base>-time.csv)${1:+; '$1' does not exist}" >&2
  exit 1
fi
csv=$1
png=${2:-"${csv%.csv}.png"}
command -v gnuplot > /dev/null || { echo "plot_time_history.sh: error: gnuplot is missing (contrib/setup.sh installs it)" >&2; exit 1; }
header=$(head -n 1 "$csv")
columns=$(tr ',' '\n' <<< "$header" | wc -l)
case "$header" in
  step,time,time_step,newton_iterations,kinetic_energy,energy,dissipated*) ;;
  *) echo "plot_time_history.sh: error: '$csv' is not the time history of a Newmark, Euler, central difference or quasistatic run (header: $header)" >&2; exit 1 ;;
esac
title=$(basename "${csv%-time.csv}")
gnuplot <<GP
set terminal pngcairo size 1000,800 font ",11" noenhanced
set output "$png"
set datafile separator ","
set multiplot layout 2,1 title "$title: time history"
set xlabel "time"
set ylabel "energy"
set key top right
plot "$csv" using 2:5 with lines lw 2 title "kinetic", \
     "$csv" using 2:7 with lines lw 2 title "dissipated D", \
     "$csv" using 2:(\$6 + \$7) with lines lw 2 title "balance E + D (E: total energy)"
set ylabel "penalty energy"
if ($columns > 7) {
  plot for [c=8:$columns] "$csv" using 2:c with lines lw 2 title columnheader(c) noenhanced
} else {
  set label 1 "no contact declared" at graph 0.5, 0.5 center
  plot NaN notitle
}
unset multiplot
GP
echo "wrote $png"
