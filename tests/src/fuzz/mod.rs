//! Fuzzing the command line in-process: command lines drawn from the
//! grammar ([`grammar`]), run through [`trig_audit::run`] on their own
//! thread (a panic is caught, a run past the time limit is a hang), and
//! their outcome judged by the [`oracle`] (one-line errors, no NaN, no
//! wrong digit against an independent reference).
//!
//! [`campaign`] draws cases from a seeded generator until a case count or
//! a deadline, so the CI run is bounded in time and the long run
//! (recorded in BENCHMARKS.md) is reproducible.

pub mod grammar;
pub mod oracle;
pub mod scratch;

use std::path::PathBuf;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use trig_audit::Outcome;

use grammar::Case;

/// What a campaign found.
#[derive(Debug, Default)]
pub struct Stats {
    pub cases: usize,
    pub outputs: usize,
    pub errors: usize,
    /// Printed values checked against the reference.
    pub values: usize,
    pub panics: Vec<(Vec<String>, String)>,
    pub hangs: Vec<Vec<String>>,
    pub wrong: Vec<(Vec<String>, String)>,
    pub elapsed: Duration,
    /// The slowest case and its time.
    pub slowest: (Duration, Vec<String>),
}

impl Stats {
    /// True when nothing went wrong.
    pub fn clean(&self) -> bool {
        self.panics.is_empty() && self.hangs.is_empty() && self.wrong.is_empty()
    }
}

impl std::fmt::Display for Stats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(
            f,
            "{} cases in {:.1} s: {} outputs, {} one-line errors, {} printed values checked; {} panics, {} hangs, {} wrong; slowest {:.2} s: {:?}",
            self.cases,
            self.elapsed.as_secs_f64(),
            self.outputs,
            self.errors,
            self.values,
            self.panics.len(),
            self.hangs.len(),
            self.wrong.len(),
            self.slowest.0.as_secs_f64(),
            self.slowest.1
        )?;
        for (args, m) in self.panics.iter().take(10) {
            writeln!(f, "PANIC {args:?}: {m}")?;
        }
        for args in self.hangs.iter().take(10) {
            writeln!(f, "HANG {args:?}")?;
        }
        for (args, m) in self.wrong.iter().take(10) {
            writeln!(f, "WRONG {args:?}: {m}")?;
        }
        Ok(())
    }
}

/// A case that did not finish normally.
#[derive(Debug)]
pub enum Failure {
    Panic(String),
    Hang,
}

/// Runs one command line (program name prepended) on a fresh thread with
/// a main-thread-sized stack, waiting at most `limit`.
pub fn run_case(args: &[String], limit: Duration) -> Result<Outcome, Failure> {
    let mut argv = vec!["trig-audit".to_string()];
    argv.extend(args.iter().cloned());
    let (tx, rx) = mpsc::channel();
    let spawned = std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || {
            let result = std::panic::catch_unwind(|| trig_audit::run(argv));
            let _ = tx.send(result.map_err(|p| {
                p.downcast_ref::<String>()
                    .cloned()
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_else(|| "non-string panic".into())
            }));
        });
    if let Err(e) = spawned {
        return Err(Failure::Panic(format!("cannot start a thread: {e}")));
    }
    match rx.recv_timeout(limit) {
        Ok(Ok(outcome)) => Ok(outcome),
        Ok(Err(message)) => Err(Failure::Panic(message)),
        Err(_) => Err(Failure::Hang),
    }
}

/// Where plot output and the hostile outline and spec go (removed after
/// a campaign).
pub fn scratch() -> PathBuf {
    std::env::temp_dir().join(format!("trig-audit-fuzz-{}", std::process::id()))
}

/// Draws cases from the grammar (seed `seed`; `heavy` adds the largest
/// precisions) and runs them until `cases` cases or `deadline`, each
/// limited to `limit`.
pub fn campaign(
    seed: u64,
    cases: usize,
    deadline: Duration,
    limit: Duration,
    heavy: bool,
) -> Stats {
    let scratch = scratch();
    scratch::write(&scratch).expect("scratch directory");
    let strategy = grammar::case(heavy, scratch.clone());
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &bytes),
    );
    let start = Instant::now();
    let mut stats = Stats::default();
    while stats.cases < cases && start.elapsed() < deadline {
        let Ok(tree) = strategy.new_tree(&mut runner) else {
            continue;
        };
        let case: Case = tree.current();
        let t = Instant::now();
        let result = run_case(&case.args, limit);
        let took = t.elapsed();
        if took > stats.slowest.0 {
            stats.slowest = (took, case.args.clone());
        }
        stats.cases += 1;
        match result {
            Err(Failure::Panic(m)) => stats.panics.push((case.args.clone(), m)),
            Err(Failure::Hang) => stats.hangs.push(case.args.clone()),
            Ok(outcome) => {
                match &outcome {
                    Outcome::Error(_) => stats.errors += 1,
                    _ => stats.outputs += 1,
                }
                match oracle::check(&case, &outcome) {
                    Ok(n) => stats.values += n,
                    Err(m) => stats.wrong.push((case.args.clone(), m)),
                }
            }
        }
    }
    stats.elapsed = start.elapsed();
    let _ = std::fs::remove_dir_all(&scratch);
    stats
}
