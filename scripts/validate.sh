#!/usr/bin/env bash
# Runs every scene of compare/scenes through `granmix theory` (and `granmix dsmc --fidelity quick`
# when the scene has a [dsmc] table), checks each output is complete and finite, and prints one
# summary line per run. Exit 1 if any fails. Deviations with tolerances come with `granmix compare`.
set -uo pipefail
exe=${1:?usage: validate.sh GRANMIX [OUT]}
out=${2:-out}
cd "$(dirname "$0")/.."
status=0
printf '%-26s %-8s %-6s %s\n' scene result rows detail
for scene in compare/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  if log=$("$exe" theory "$scene" --out "$out" 2>&1); then
    file="$out/$name/theory.tsv"
    rows=$(grep -vc '^#' "$file")
    rows=$((rows - 1))
    # No infinite values (nan is allowed: it marks a column that does not apply to a row).
    bad=$(grep -v '^#' "$file" | tail -n +2 | grep -Eci '(^|[[:space:]])[-+]?inf' || true)
    if [ "$rows" -gt 0 ] && [ "$bad" -eq 0 ]; then
      printf '%-26s %-8s %-6s %s\n' "$name" pass "$rows" "${log#*: }"
    else
      printf '%-26s %-8s %-6s %s\n' "$name" FAIL "$rows" "non-finite values or no rows"
      status=1
    fi
  else
    printf '%-26s %-8s %-6s %s\n' "$name" FAIL - "$log"
    status=1
  fi
  if grep -q '^\[dsmc\]' "$scene"; then
    if log=$("$exe" dsmc "$scene" --out "$out" --fidelity quick 2>&1); then
      rows=$(($(grep -vc '^#' "$out/$name/dsmc.tsv") - 1))
      printf '%-26s %-8s %-6s %s\n' "$name (dsmc)" pass "$rows" "$(echo "$log" | tail -1 | sed 's/^ *//')"
    else
      printf '%-26s %-8s %-6s %s\n' "$name (dsmc)" FAIL - "$log"
      status=1
    fi
  fi
done
"$exe" hcs --mu 10 --delta 2 --w 1 --alpha 0.5 --json > "$out/hcs-mg-fig01.json" || status=1
echo "hcs (MG Fig. 1 parameters): $(cat "$out/hcs-mg-fig01.json")"
[ $status -eq 0 ] && echo "validate: all scenes pass (theory, and DSMC where a scene has [dsmc])" || echo "validate: FAILED"
exit $status
