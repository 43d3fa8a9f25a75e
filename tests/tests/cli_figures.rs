//! The figures the audit report links (`trig_verification::figures`): each is
//! drawn by the `trig-audit` command it states, into a scratch directory here
//! (or over the committed file with `TRIG_AUDIT_REDRAW_FIGURES=1`, which is
//! what `./run.sh figures` does), and the committed file exists.

use std::path::{Path, PathBuf};

use trig_verification::figures::FIGURES;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

#[test]
fn every_linked_figure_is_drawn_by_its_command_and_committed() {
    let redraw = std::env::var_os("TRIG_AUDIT_REDRAW_FIGURES").is_some();
    let scratch = std::env::temp_dir().join(format!("trig-audit-figures-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).expect("scratch directory");
    for f in FIGURES {
        let target = if redraw {
            root().join(f.path)
        } else {
            scratch.join(Path::new(f.path).file_name().expect("file name"))
        };
        let target = target.to_string_lossy().into_owned();
        let args: Vec<&str> = f
            .command
            .split_whitespace()
            .map(|a| if a == f.path { target.as_str() } else { a })
            .collect();
        let out = trig_e2e::written(&args);
        assert!(out.contains("wrote"), "{}: {out}", f.claim);
        let svg = std::fs::read_to_string(&target).expect("figure written");
        assert!(
            svg.starts_with("<svg") || svg.starts_with("<?xml"),
            "{}",
            f.claim
        );
        let data = std::fs::read_to_string(Path::new(&target).with_extension("csv"))
            .expect("the data written beside the figure");
        assert!(data.starts_with("series,point,x,y\n"), "{}", f.claim);
        assert!(root().join(f.path).exists(), "{} is not committed", f.path);
        assert!(
            root().join(f.data_path()).exists(),
            "{} is not committed",
            f.data_path()
        );
    }
    let _ = std::fs::remove_dir_all(&scratch);
}
