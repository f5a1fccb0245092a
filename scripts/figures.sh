#!/usr/bin/env bash
# Figures of every scene already computed under OUT (by `make validate`): a PNG beside each
# theory.tsv, theory as lines and DSMC (when dsmc.tsv is there) as symbols with error bars,
# drawn with plots/style.gp. Needs gnuplot; without it the data stays and this
# script says how to get the figures.
set -euo pipefail
out=${1:-out}
cd "$(dirname "$0")/.."
if ! command -v gnuplot > /dev/null; then
  echo "figures: gnuplot not found; install it with 'apt-get install gnuplot-nox' (make deps does) and rerun 'make figures'"
  exit 0
fi
for tsv in "$out"/*/theory.tsv; do
  dir=$(dirname "$tsv")
  name=$(basename "$dir")
  header=$(grep -v '^#' "$tsv" | head -1)
  species=$(grep -v '^#' "$tsv" | tail -n +2 | cut -f2 | sort -n | uniq | tail -1)
  title=$(grep -m1 '^title' "compare/scenes/$name.toml" 2>/dev/null | sed 's/^title *= *"\(.*\)"/\1/' || true)
  case "$header" in
    eps*) x=eps; y=D_ratio; logs="" ; xl="restitution coefficient ε"; yl="D_k / D_1"; first=2 ;;
    t*msd*) x=t; y=msd; logs="set logscale xy; set format xy '10^{%T}'"; xl="t"; yl="⟨R_k^2(t)⟩"; first=0 ;;
    *) x=t; y=T; logs="set logscale xy; set format xy '10^{%T}'"; xl="t"; yl="T_k(t)"; first=1 ;;
  esac
  # Long form: rows cycle through the species present (0 first when there is a total row), so
  # species k is every stride-th row from its offset; NaN-filtering would break every line.
  lowest=$(grep -v '^#' "$tsv" | tail -n +2 | cut -f2 | sort -n | head -1)
  stride=$((species - lowest + 1))
  plot=""
  for k in $(seq "$first" "$species"); do
    label="species $k"; style="ls $((k > 0 ? k : 9))"
    [ "$k" -eq 0 ] && label="total"
    plot+="${plot:+, }'$tsv' every $stride::$((k - lowest)) using (column('$x')):(column('$y')) with lines $style title '$label'"
    # DSMC beside theory: symbols with standard-error bars, same rows and colours.
    if [ -f "$dir/dsmc.tsv" ] && grep -v '^#' "$dir/dsmc.tsv" | head -1 | grep -qw "${y}_err"; then
      plot+=", '$dir/dsmc.tsv' every $stride::$((k - lowest)) using (column('$x')):(column('$y')):(column('${y}_err')) with yerrorbars $style pt 7 ps 0.6 title '$label DSMC'"
    fi
  done
  gnuplot -e "load 'plots/style.gp'; set output '$dir/$name.png'; $logs; set xlabel \"$xl\"; set ylabel \"$yl\"; set title \"$title\" noenhanced; plot $plot"
  echo "figures: $dir/$name.png"
done
