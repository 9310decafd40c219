#!/usr/bin/env bash
# The combine as a separator (issue 56), from a run of configs/combine-separation.json:
#   - map.csv and map.md: per map run (map_u<inflow>_<feed>), at its last series row, the fed grain
#     and chaff (kg), the share of each that left through the right (x_high) and top (y_high)
#     outlets, and the Eq. 4.1 mean heights;
#   - map.png: chaff removed and grain lost (% of fed, both outlets) against the air inflow, one
#     curve per feed (the curve a cleaning-shoe designer reads);
#   - heights.png: the grain's and the chaff's mean height against time, every map run;
#   - changes.md: the one-change runs (change_*) and the two base runs they differ from
#     (map_u085_dense, and map_u085_dilute, the feed spread over a taller patch) at 1, 2 and 3 s:
#     mean heights and the chaff out through each outlet.
# Usage: scripts/combine-separation.sh RESULTS_DIR [OUT_DIR]
#   RESULTS_DIR: results/combine-separation (the workflow's results, one folder per stage)
set -euo pipefail
results=${1:?usage: scripts/combine-separation.sh RESULTS_DIR [OUT_DIR]}
out=${2:-$results/separation}
mkdir -p "$out"
rm -f "$out"/heights-*.dat "$out"/map-*.dat  # a rerun over fewer runs leaves none of the last one's

# The series.csv of a stage (its one instance), or nothing when the stage has not finished.
series_of() {
  local found
  found=$(find "$results/$1" -mindepth 2 -maxdepth 2 -name series.csv -not -path '*.partial/*' 2>/dev/null | head -1)
  echo "$found"
}

# Columns by name from a series' header: prints the awk program's column indices as name=index.
columns() { head -1 "$1" | tr ',' '\n' | awk '{printf "-v c_%s=%d ", $1, NR}'; }

echo "stage,inflow_m_s,feed,t_s,grain_fed_kg,chaff_fed_kg,grain_out_right_pct,grain_out_top_pct,chaff_out_right_pct,chaff_out_top_pct,grain_lost_kg,grain_lost_pct,chaff_removed_pct,h_grain_cm,h_chaff_cm,grain_lost_5s_pct,chaff_removed_5s_pct,first_grain_out_s" >"$out/map.csv"
for dir in "$results"/map_u*; do
  [ -d "$dir" ] || continue
  stage=$(basename "$dir")
  s=$(series_of "$stage")
  if [ -z "$s" ]; then
    echo "combine-separation: $stage has no finished series.csv (failed or still running): left out" >&2
    continue
  fi
  u=$(echo "$stage" | sed -E 's/map_u([0-9]+)_.*/\1/')
  inflow=$(awk -v u="$u" 'BEGIN { printf "%.2f", (length(u) == 2 ? u / 10 : u / 100) }')
  feed=${stage##*_}
  # The last row, the row nearest 5 s, and the first time more than a gram of grain has left.
  # shellcheck disable=SC2046
  awk -F, $(columns "$s") -v stage="$stage" -v inflow="$inflow" -v feed="$feed" 'NR > 1 {
    gin = $c_mass_in_grain; cin = $c_mass_in_chaff
    gr = $c_mass_out_grain_x_high; gt = $c_mass_out_grain_y_high
    cr = $c_mass_out_chaff_x_high; ct = $c_mass_out_chaff_y_high
    t = $c_time; hg = $c_mean_height_grain; hc = $c_mean_height_chaff
    d = t - 5; if (d < 0) d = -d
    if (best == "" || d < best) { best = d; lost5 = 100 * (gr + gt) / gin; removed5 = 100 * (cr + ct) / cin }
    if (first == "" && gr + gt > 1e-3) first = sprintf("%.2f", t)
  } END {
    if (first == "") first = "-"
    printf "%s,%s,%s,%.2f,%.4f,%.4f,%.3f,%.3f,%.2f,%.2f,%.4f,%.3f,%.2f,%.2f,%.2f,%.3f,%.2f,%s\n", stage, inflow, feed, t,
      gin, cin, 100 * gr / gin, 100 * gt / gin, 100 * cr / cin, 100 * ct / cin, gr + gt, 100 * (gr + gt) / gin,
      100 * (cr + ct) / cin, 100 * hg, 100 * hc, lost5, removed5, first
  }' "$s" >>"$out/map.csv"
done
sort -t, -k3,3 -k2,2n -o "$out/map.csv.body" <(tail -n +2 "$out/map.csv")
{ head -1 "$out/map.csv"; cat "$out/map.csv.body"; } >"$out/map.csv.sorted" && mv "$out/map.csv.sorted" "$out/map.csv"
rm -f "$out/map.csv.body"

{
  echo "| inflow [m/s] | feed | t [s] | grain fed [kg] | grain out right / top [%] | grain lost [kg] | chaff fed [kg] | chaff out right / top [%] | chaff removed [%] | <h> grain / chaff [cm] | at 5 s: grain lost / chaff removed [%] | grain out from [s] |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  tail -n +2 "$out/map.csv" | awk -F, '{ printf "| %s | %s | %s | %s | %s / %s | %s | %s | %s / %s | %s | %s / %s | %s / %s | %s |\n",
    $2, $3, $4, $5, $7, $8, $11, $6, $9, $10, $13, $14, $15, $16, $17, $18 }'
} >"$out/map.md"

# The Eq. 4.1 heights of every map run at 1, 3, 5 and 10 s (the series row nearest each).
{
  echo
  echo "| inflow [m/s] | feed | <h> grain / chaff at 1 s [cm] | at 3 s | at 5 s | at 10 s |"
  echo "|---|---|---|---|---|---|"
  tail -n +2 "$out/map.csv" | while IFS=, read -r stage inflow feed _; do
    s=$(series_of "$stage")
    # shellcheck disable=SC2046
    awk -F, $(columns "$s") -v inflow="$inflow" -v feed="$feed" 'BEGIN { n = split("1 3 5 10", at, " ") }
      NR > 1 { for (k = 1; k <= n; ++k) { d = $c_time - at[k]; if (d < 0) d = -d
        if (!(k in best) || d < best[k]) { best[k] = d; h[k] = sprintf("%.1f / %.1f", 100 * $c_mean_height_grain, 100 * $c_mean_height_chaff) } } }
      END { printf "| %s | %s | %s | %s | %s | %s |\n", inflow, feed, h[1], h[2], h[3], h[4] }' "$s"
  done
} >>"$out/map.md"

for feed in dense dilute; do
  awk -F, -v feed="$feed" 'NR > 1 && $3 == feed { print $2, $12, $13 }' "$out/map.csv" >"$out/map-$feed.dat"
done
[ "$(wc -l <"$out/map.csv")" -gt 1 ] && gnuplot <<EOF
set terminal pngcairo noenhanced size 900,600
set output "$out/map.png"
set title "The combine as a separator (configs/combine-separation.json, 10 s)"
set xlabel "air inflow through the bottom [m/s]"
set ylabel "chaff removed [% of fed]"
set y2label "grain lost [% of fed]"
set ytics nomirror
set y2tics
set key top left
set grid
plot "$out/map-dense.dat" using 1:3 with linespoints lw 2 pt 7 title "chaff removed, feed 0.60", \
     "$out/map-dilute.dat" using 1:3 with linespoints lw 2 pt 5 title "chaff removed, feed 0.20 (3x taller)", \
     "$out/map-dense.dat" using 1:2 axes x1y2 with linespoints lw 2 dt 2 pt 6 title "grain lost, feed 0.60", \
     "$out/map-dilute.dat" using 1:2 axes x1y2 with linespoints lw 2 dt 2 pt 4 title "grain lost, feed 0.20 (3x taller)"
EOF

# The heights against time: one file per map run (time, grain, chaff in cm), one panel per feed.
panel() {  # the plot command of one feed's runs
  local feed=$1 list=() u
  for dat in "$out"/heights-map_u*_"$feed".dat; do
    [ -e "$dat" ] || continue
    u=$(basename "$dat" | sed -E 's/heights-map_u([0-9]+)_.*/\1/')
    u=$(awk -v u="$u" 'BEGIN { printf "%.2f", (length(u) == 2 ? u / 10 : u / 100) }')
    list+=("\"$dat\" using 1:3 with lines lw 2 lc $((${#list[@]} / 2 + 1)) title \"$u m/s chaff\"")
    list+=("\"$dat\" using 1:2 with lines dt 2 lc $((${#list[@]} / 2 + 1)) title \"$u m/s grain\"")
  done
  local joined
  joined=$(printf '%s, ' "${list[@]}")
  echo "plot ${joined%, }"
}
for dir in "$results"/map_u*; do
  stage=$(basename "$dir")
  s=$(series_of "$stage")
  [ -n "$s" ] || continue
  # shellcheck disable=SC2046
  awk -F, $(columns "$s") 'NR > 1 { print $c_time, 100 * $c_mean_height_grain, 100 * $c_mean_height_chaff }' "$s" \
    >"$out/heights-$stage.dat"
done
if compgen -G "$out/heights-map_u*.dat" >/dev/null; then
  gnuplot <<EOF
set terminal pngcairo noenhanced size 1200,550
set output "$out/heights.png"
set multiplot layout 1,2 title "Eq. 4.1 mean heights against time (chaff solid, grain dashed)"
set xlabel "t [s]"
set ylabel "mean height [cm]"
set yrange [0:45]
set grid
set key top right
set title "feed 0.60 over y 36-48 cm (Table 4.4)"
$(if compgen -G "$out/heights-map_u*_dense.dat" >/dev/null; then panel dense; else echo "plot 0 notitle"; fi)
set title "feed 0.20 over y 12-48 cm (the same mass flow)"
$(if compgen -G "$out/heights-map_u*_dilute.dat" >/dev/null; then panel dilute; else echo "plot 0 notitle"; fi)
unset multiplot
EOF
fi

# The one-change runs against their bases at 1, 2 and 3 s.
{
  echo "| run | t [s] | <h> grain [cm] | <h> chaff [cm] | chaff out right / top [% of fed] |"
  echo "|---|---|---|---|---|"
  for stage in map_u085_dense map_u085_dilute $(cd "$results" && ls -d change_* 2>/dev/null); do
    s=$(series_of "$stage")
    [ -n "$s" ] || continue
    for t in 1 2 3; do
      # shellcheck disable=SC2046
      awk -F, $(columns "$s") -v t="$t" -v stage="$stage" 'NR > 1 {
        d = $c_time - t; if (d < 0) d = -d
        if (best == "" || d < best) { best = d; row = $0 }
      } END {
        split(row, f, ",")
        cin = f[c_mass_in_chaff]
        printf "| %s | %.2f | %.1f | %.1f | %.2f / %.2f |\n", stage, f[c_time], 100 * f[c_mean_height_grain],
          100 * f[c_mean_height_chaff], 100 * f[c_mass_out_chaff_x_high] / cin, 100 * f[c_mass_out_chaff_y_high] / cin
      }' "$s"
    done
  done
} >"$out/changes.md"
echo "combine-separation: $out/map.csv, map.md, map.png, heights.png, changes.md"
