# Issue 16 convergence picture: peak force against equations, docs/validation.md §19.
# Data: docs/notes/decks/peak-force-vs-dofs.sh > docs/notes/decks/peak-force-vs-dofs.csv
# Redraw (from the repository root): gnuplot docs/images/peak-force-vs-dofs.gp
set terminal pngcairo size 1400,800 font "DejaVu Sans,11"
set output "docs/images/peak-force-vs-dofs.png"
set datafile separator ","
csv = "docs/notes/decks/peak-force-vs-dofs.csv"
set multiplot layout 1,2 title "Peak contact force vs mesh size (uniform meshes; star: default graded deck)"
set logscale x
set xrange [1200:40000]
set xtics (1500, 2000, 3000, 5000, 10000, 20000, 30000)
set xlabel "equations"
set ylabel "peak force (N)"
set grid
set key below horizontal maxcols 2 width -8 font ",10"
array S[4] = ["q9 point", "q9 hertz-pressure", "mitc9 point", "mitc9 hertz-pressure"]
colour(i) = word("#d62728 #ff7f0e #1f77b4 #2ca02c", i)
do for [c in "ii iii"] {
  ref = (c eq "ii") ? 2544.06 : 447.94
  set title (c eq "ii") ? "(ii) [0_2/90_4/0_2], 0.314 kg at 2.92 m/s" : "(iii) same plate, 8.4 g steel ball at 3 m/s"
  plot for [i=1:4] csv using (strcol(1) eq c && strcol(2) eq sprintf("%s centre", S[i]) ? $5 : NaN):6 \
         every ::1 with linespoints lw 2 pt 7 lc rgb colour(i) title sprintf("%s, centre node", S[i]), \
       for [i=1:4] csv using (strcol(1) eq c && strcol(2) eq sprintf("%s corner", S[i]) ? $5 : NaN):6 \
         every ::1 with linespoints lw 2 dt 2 pt 5 lc rgb colour(i) title sprintf("%s, corner node", S[i]), \
       csv using (strcol(1) eq c && strcol(2) eq "mitc9 hertz-pressure graded" ? $5 : NaN):6 every ::1 \
         with points pt 3 ps 3 lw 2 lc rgb "black" title "default (graded MITC9, Hertz pressure)", \
       ref with lines lw 1 dt 3 lc rgb "black" title sprintf("Navier reference %.2f N", ref)
}
unset multiplot
