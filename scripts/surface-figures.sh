#!/bin/sh
# Redraws the thesis's surface figures (seed 001, Chapter 5) into
# docs/figures/ from its printed control net (examples/surfaces/thesis-net.txt)
# and the parameter values its text gives (docs/surfaces.md says which are
# chosen where the text gives none). Run from the repository root.
set -eu
plot() { cargo run -q -p trig-audit -- plot surface --family thesis-cubic --net examples/surfaces/thesis-net.txt "$@"; }
plot --param m=1 --output docs/figures/surface-5.1.svg
for m in -1.8 -1 0 1; do
  plot --param "m=$m" --output "docs/figures/surface-5.2-m$m.svg"
done
for m in -4 -3 3 4; do
  plot --param "m=$m" --allow-outside-range --output "docs/figures/surface-5.3-m$m.svg"
done
plot --param m=1 --join c1 --param2 m=0.5 --output docs/figures/surface-5.4-c1.svg
plot --param m=1 --join c2 --param2 m=0.5 --output docs/figures/surface-5.5-c2.svg
plot --param m=0.5 --join g1 --alpha 2 --output docs/figures/surface-5.6-g1.svg
plot --param m=0.5 --join g2 --param2 m=0.2 --alpha 0.5 --beta 2 --output docs/figures/surface-5.7-g2.svg
# a surface of revolution: the vase profile (thesis cubic, m = 0) swept by the
# exact quarter circle of Han's quadratic at λ = 0 (not a thesis figure)
cargo run -q -p trig-audit -- plot surface --family thesis-cubic --param m=0 --net examples/surfaces/vase-profile.txt \
  --revolution --v-spec examples/han-quadratic.toml --v-param lambda=0 --elevation 20 --output docs/figures/surface-revolution-vase.svg
# the cylinders (the thesis prints no net for them: examples/surfaces/half-cylinder-net.txt is ours)
plot_cylinder() { cargo run -q -p trig-audit -- plot surface --family thesis-cubic --net examples/surfaces/half-cylinder-net.txt --close "$@"; }
plot_cylinder --param m=0.7 --join c1 --output docs/figures/surface-5.9-c1-cylinder.svg
plot_cylinder --param m=1 --join g1 --alpha 2 --output docs/figures/surface-5.11-g1-cylinder.svg
# C2 and G2 (Figures 5.10(a), 5.12(a) values): both patches solved together; flat (docs/surfaces.md)
plot_cylinder --param m=1 --join c2 --param2 m=0.5 --output docs/figures/surface-5.10-c2-cylinder.svg
plot_cylinder --param m=0.5 --join g2 --param2 m=0.2 --alpha 0.5 --beta 2 --output docs/figures/surface-5.12-g2-cylinder.svg
