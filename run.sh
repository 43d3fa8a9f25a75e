#!/usr/bin/env bash
# One entry point for a fresh machine: installs what the build needs, then runs.
#   ./run.sh audit [ARGS...]   the main job: the audit report (Markdown on stdout;
#                              ARGS go to `trig-audit audit`, e.g. --format json
#                              --output report.json)
#   ./run.sh test              the whole test suite (what CI runs)
#   ./run.sh lint              rustfmt check, clippy and rustdoc with -D warnings
#   ./run.sh bench             criterion benchmarks (figures in BENCHMARKS.md)
#   ./run.sh figures           redraw the figures the audit report links (docs/figures/)
#
# Standard output carries only the command's own output (the report):
# installers and cargo's build progress go to standard error.
set -euo pipefail
cd "$(dirname "$0")"

as_root() {
  if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi
}

# apt-get quietly: one line saying what is installed; apt's own output goes
# to a log that is shown (on standard error) only when the install fails.
install_packages() {
  echo "run.sh: installing $* (apt-get)" >&2
  local log
  log=$(mktemp)
  if ! {
    as_root apt-get update -qq &&
      DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -qq "$@"
  } >"$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    echo "run.sh: apt-get could not install $*" >&2
    return 1
  fi
  rm -f "$log"
}

# True when the system's GMP and MPFR headers are recent enough for
# gmp-mpfr-sys 1.7 (GMP >= 6.3, MPFR >= 4.2): then rug links them.
system_gmp_usable() {
  command -v cc >/dev/null 2>&1 || return 1
  printf '%s\n' '#include <gmp.h>' '#include <mpfr.h>' \
    '#if __GNU_MP_VERSION < 6 || (__GNU_MP_VERSION == 6 && __GNU_MP_VERSION_MINOR < 3)' \
    '#error GMP older than 6.3' '#endif' \
    '#if MPFR_VERSION < MPFR_VERSION_NUM(4, 2, 0)' '#error MPFR older than 4.2' '#endif' |
    cc -E -x c - >/dev/null 2>&1
}

# GMP and MPFR behind rug: the distribution's libgmp-dev and libmpfr-dev when
# they are (or can be installed) recent enough -- Debian 13 has GMP 6.3.0 and
# MPFR 4.2.2; Debian 12's GMP 6.2.1 is too old for gmp-mpfr-sys 1.7 -- else
# built from source once (needs m4), cached in ~/.cache/gmp-mpfr-sys and
# without their own test suites (feature c-no-tests).
FEATURES=()
prepare_gmp() {
  if system_gmp_usable; then
    FEATURES=(--features trig-core/system-gmp)
    return
  fi
  if command -v apt-cache >/dev/null 2>&1; then
    local candidate
    candidate=$(apt-cache policy libgmp-dev 2>/dev/null | awk '/Candidate:/ {print $2}')
    if [ -n "$candidate" ] && [ "$candidate" != "(none)" ] &&
      dpkg --compare-versions "$candidate" ge "2:6.3"; then
      install_packages libgmp-dev libmpfr-dev
      if system_gmp_usable; then
        FEATURES=(--features trig-core/system-gmp)
        return
      fi
    fi
  fi
  if ! command -v m4 >/dev/null 2>&1; then
    install_packages m4
  fi
}

# A minimal TeX for the tests that compile the LaTeX outputs (reports,
# tables, figures, a paper that \input's them): pdflatex with booktabs,
# longtable and pgfplots -- Debian's texlive-latex-base,
# texlive-latex-recommended and texlive-pictures (about 20 s to install).
# Under ./run.sh test the compile tests then must run: without TeX they fail
# (TRIG_AUDIT_REQUIRE_TEX) instead of being skipped.
prepare_tex() {
  if command -v pdflatex >/dev/null 2>&1 &&
    kpsewhich booktabs.sty longtable.sty pgfplots.sty >/dev/null 2>&1 &&
    [ "$(kpsewhich booktabs.sty longtable.sty pgfplots.sty | wc -l)" = 3 ]; then
    return
  fi
  if command -v apt-get >/dev/null 2>&1; then
    install_packages --no-install-recommends texlive-latex-base \
      texlive-latex-recommended texlive-pictures
  else
    echo "run.sh: pdflatex with booktabs, longtable and pgfplots is needed for the LaTeX compile tests" >&2
  fi
}

cmd="${1:-}"
shift || true
case "$cmd" in
  audit | test | lint | bench | figures) prepare_gmp ;;
  *) echo "usage: ./run.sh audit|test|lint|bench|figures" >&2; exit 2 ;;
esac
# The audit runs in the dev profile, which is also the test profile: it is
# optimised where the arithmetic runs (Cargo.toml), decides the audit about as
# fast as a release build, compiles in far less time on a fresh machine and
# shares its build with `./run.sh test` (BENCHMARKS.md).
case "$cmd" in
  audit) cargo run -p trig-audit "${FEATURES[@]}" -- audit "$@" ;;
  test)
    prepare_tex
    TRIG_AUDIT_REQUIRE_TEX=1 cargo test --workspace "${FEATURES[@]}"
    ;;
  lint)
    cargo fmt --all --check
    cargo clippy --workspace --all-targets "${FEATURES[@]}" -- -D warnings
    RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps "${FEATURES[@]}"
    ;;
  bench) cargo bench --workspace "${FEATURES[@]}" ;;
  figures) TRIG_AUDIT_REDRAW_FIGURES=1 cargo test -p trig-e2e --test e2e cli_figures "${FEATURES[@]}" ;;
esac
