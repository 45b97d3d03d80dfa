#!/usr/bin/env bash
# Regenerates the example tables of README.md; with --check, compares instead of writing.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
B=target/release/fricosc
check=${1:-}
emit() { # emit FILE command...
  local file=$1; shift
  if [ "$check" = "--check" ]; then
    if ! diff -q <("$@") "$file" >/dev/null; then echo "stale: $file (run bash data/regenerate.sh)" >&2; exit 1; fi
  else
    "$@" > "$file"
  fi
}
emit data/flat-fig3.csv $B table --shape flat --amp 0,0.2,0.4,0.6,0.8,1.0 --vbar 0:1.2:13 --format csv
emit data/flat-fig5.csv $B table --shape flat --amp 1:2:11 --vbar 0:1.2:13 --format csv
emit data/parabolic-fig7.csv $B table --shape parabolic --amp 0,0.2,0.4,0.6,0.8,1.0 --vbar 0:1.2:13 --format csv
emit data/point-flat.json $B point --shape flat --vbar 0.3 --amp 1.5
emit data/point-parabolic.json $B point --shape parabolic --vbar 0.6 --amp 1
emit data/stepped-flat.csv $B table --shape flat --amp 0.5,1.5 --vbar 0.1:0.9:3 --method stepping --steps-per-period 1000 --format csv
emit data/stepped-flat-validation.json $B validate --shape flat data/stepped-flat.csv --max-error 1e-3
emit data/point-combined-flat.json $B point --shape flat --vhat 0.3 --amp 1.5 --tangential-amp 2 --phase 1.2
emit data/table-combined.csv $B table --shape parabolic --vhat 0.3 --amp 0.5,1.5 --tangential-amp 2 --phase 0,1.2,3.1416,4.2 --format csv
emit data/point-sphere.json $B point --shape profile:data/profiles/sphere.csv@1e-6 --vbar 0.3 --amp 0.4
emit data/claims.md $B claims
emit data/scene-steel-sphere-fig9.out.json $B scene data/scenes/steel-sphere-fig9.json
emit data/scene.schema.json $B scene --schema
emit data/scene-tribometer-pin.out.json $B scene data/scenes/tribometer-pin.json
emit data/fit-example.out.json $B fit data/fit-example.csv --format json
emit data/history-flat.csv $B history --shape flat --vbar 0.3 --amp 0.5 --samples 200 --format csv
emit data/history-flat.svg $B history --shape flat --vbar 0.3 --amp 0.5 --samples 400 --format svg
emit data/history-flat.png $B history --shape flat --vbar 0.3 --amp 0.5 --samples 400 --format png
# A command that writes its drawing to the file named last (plot --out FILE).
emit_to() { # emit_to FILE command...
  local file=$1; shift
  if [ "$check" = "--check" ]; then
    local tmp; tmp=$(mktemp -d)/$(basename "$file")
    "$@" "$tmp" > /dev/null
    if ! cmp -s "$tmp" "$file"; then echo "stale: $file (run bash data/regenerate.sh)" >&2; exit 1; fi
  else
    "$@" "$file" > /dev/null
  fi
}
emit_to data/plot-parabolic.png $B plot --shape parabolic --amp 0:3:7 --vhat 0:2:201 --out
emit_to data/scene-steel-sphere-fig9.png $B scene data/scenes/steel-sphere-fig9.json --plot
emit_to data/fit-example.png $B fit data/fit-example.csv --format json --plot
if [ "$check" = "--check" ]; then
  tmp=$(mktemp -d)
  $B figures --out "$tmp" > /dev/null
  if ! diff -rq "$tmp" data/figures > /dev/null; then echo "stale: data/figures (run bash data/regenerate.sh)" >&2; exit 1; fi
  rm -rf "$tmp"
else
  $B figures --out data/figures > /dev/null
fi
echo "data/ is up to date"
