#!/usr/bin/env bash
# One entry point for a fresh machine: installs what the build needs, then runs.
#   ./run.sh audit [ARGS...]   the main job: the audit report (Markdown on stdout;
#                              ARGS go to `trig-audit audit`, e.g. --format json
#                              --output report.json)
#   ./run.sh test              the whole test suite (what CI runs)
#   ./run.sh lint              rustfmt check and clippy with -D warnings
#   ./run.sh bench             criterion benchmarks (figures in BENCHMARKS.md)
#   ./run.sh figures           redraw the figures the audit report links (docs/figures/)
set -euo pipefail
cd "$(dirname "$0")"

ensure_m4() {
  # GMP's build (behind rug) needs m4.
  if command -v m4 >/dev/null 2>&1; then return; fi
  echo "run.sh: installing m4 (needed to build GMP/MPFR)" >&2
  local sudo=""
  if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq m4
}

cmd="${1:-}"
shift || true
ensure_m4
case "$cmd" in
  audit) cargo run --release --quiet -p trig-audit -- audit "$@" ;;
  test)  cargo test --workspace --quiet ;;
  lint)  cargo fmt --all --check && cargo clippy --workspace --all-targets --quiet -- -D warnings ;;
  bench) cargo bench --workspace ;;
  figures) TRIG_AUDIT_REDRAW_FIGURES=1 cargo test --quiet -p trig-e2e --test cli_figures ;;
  *) echo "usage: ./run.sh audit|test|lint|bench|figures" >&2; exit 2 ;;
esac
