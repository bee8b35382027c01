# The figure of prm/studies/materials.prm for doc/users/choosing.md: every
# model's torque difference from neo-Hookean against its wall time, one
# labelled point per model. Run from the repository root after the study:
#
#   gnuplot contrib/plot_materials_study.gp
set datafile separator ","
set terminal pngcairo size 800,560
set output "doc/figures/study_materials.png"
set logscale y
set xlabel "wall time of the run (s), 9 963 unknowns, UMFPACK"
set ylabel "torque: relative difference from neo-Hookean"
set title "90 degree twist, same small-strain mu and lambda"
set grid
set key off
set xrange [0:9]
set yrange [5e-4:100]
# columns: 1 model, 2 fibers, 7 Newton, 9 wall time, 12 error
plot "doc/figures/study_materials.csv" every ::1 using 9:($12 > 0 ? $12 : 1/0) with points pt 7 ps 1.5, \
     "" every ::1 using 9:($12 > 0 ? $12 : 1/0):(sprintf("%s%s (%d its)", stringcolumn(1), stringcolumn(2) eq "true" ? " + fibers" : "", $7)) with labels offset 0,1 font ",9"
