//! The fuzz suite: command lines drawn from the CLI grammar, run
//! in-process; no panic, no hang, one-line errors, no NaN, and no printed
//! digit that an independent reference (plain MPFR, ≥ 1000 bits)
//! contradicts. The CI run is bounded in time; the long run is
//! `cargo test --release -p trig-e2e --test e2e fuzz -- --ignored`
//! (`FUZZ_CASES`, `FUZZ_SEED`; figures in BENCHMARKS.md).

use std::time::Duration;

use trig_e2e::fuzz::campaign;

/// A few seconds of CI: a fixed seed, at most 2000 cases or 6 s.
#[test]
fn hostile_command_lines_in_ci() {
    let stats = campaign(
        14,
        2000,
        Duration::from_secs(6),
        Duration::from_secs(60),
        false,
    );
    println!("{stats}");
    assert!(stats.cases >= 50, "too few cases ran: {stats}");
    assert!(stats.values > 0, "no value was checked: {stats}");
    assert!(stats.clean(), "{stats}");
}

/// The long run: ≥ 100,000 cases, the heaviest precisions included.
#[test]
#[ignore = "long run (minutes): cargo test --release -p trig-e2e --test e2e fuzz -- --ignored"]
fn hostile_command_lines_long_run() {
    let cases = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100_000);
    let seed = std::env::var("FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2024);
    let stats = campaign(
        seed,
        cases,
        Duration::from_secs(24 * 3600),
        Duration::from_secs(120),
        true,
    );
    println!("{stats}");
    assert!(stats.clean(), "{stats}");
}
