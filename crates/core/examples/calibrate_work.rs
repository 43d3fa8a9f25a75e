use rug::Rational;
use trig_core::{Family, certified::enclose_basis, work};
fn main() {
    for fam in [Family::ThesisCubic, Family::Han, Family::Seed002Quartic] {
        for bits in [64u32, 256, 1024, 4096, 16384, 65536] {
            let t = std::time::Instant::now();
            let n = if bits > 4096 { 3 } else { 200 };
            let half = [Rational::from((1, 2))];
            let p = &half[..fam.info().params.len()];
            let (_, units) = work::measure(|| {
                for _ in 0..n {
                    let _ = enclose_basis(&fam, &Rational::from((1, 3)), p, bits);
                }
            });
            let dt = t.elapsed().as_secs_f64();
            println!(
                "{:?} bits {bits}: {} units/eval, {:.3e} s/eval, {:.3e} units/s",
                fam,
                units / n,
                dt / n as f64,
                units as f64 / dt
            );
        }
    }
}
