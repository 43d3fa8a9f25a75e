//! An umbrella claim's verdict from the verdicts of the claims it lists
//! (`check = "all"`).

use trig_verdict::{Evidence, Status, Verdict};

/// How an umbrella claim is decided, as the report states it.
const UMBRELLA: &str = "every listed claim of the file, each decided as it is stated: the umbrella holds when every part holds, fails when one fails";

/// How a brief umbrella is decided, as the report states it.
const BRIEF: &str =
    "umbrella: holds only if every part holds (each part is reported as its own claim)";

/// An umbrella's verdict from its parts' (`brief`: each part's verdict and
/// the first witness of one that does not hold, the parts being reported
/// as claims of their own).
pub fn umbrella_verdict(parts: Vec<(String, Verdict)>, brief: bool) -> Verdict {
    if brief {
        brief_umbrella(parts)
    } else {
        Verdict::all(UMBRELLA, parts)
    }
}

/// An umbrella over separately reported claims (T24 over T24a–f): a
/// conjunction whose evidence is one line per part with its verdict, and,
/// for each part that does not hold, its first witness.
fn brief_umbrella(parts: Vec<(String, Verdict)>) -> Verdict {
    let status = Status::conjunction(parts.iter().map(|(_, v)| v.status));
    let mut evidence = Vec::new();
    for (name, v) in parts {
        let mut line = Evidence::note(format!("reported as claim {name}"));
        line.subject = Some(name.clone());
        line.status = Some(v.status);
        evidence.push(line);
        if v.status != Status::Holds
            && let Some(w) = v
                .evidence
                .into_vec()
                .into_iter()
                .find(|e| e.witness.is_some())
        {
            evidence.push(w.in_part(name, v.status));
        }
    }
    Verdict::new(status, BRIEF, evidence)
}
