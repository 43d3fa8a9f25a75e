//! What a request for `N` significant digits delivered, said where each
//! value is printed: a value with fewer proved digits is marked, an
//! enclosure of zero proves no digit (a tiny value has digits of its own,
//! zero has none), and an exact zero is called so. Headers claim "all
//! proved" only when every value has its `N` digits.

use trig_core::Decimal;
use trig_core::certified::{Stop, WORK_BUDGET};

/// Why fewer digits than requested are proved (after "… proved").
pub fn shortfall(bits: u32, stopped: Option<Stop>) -> String {
    match stopped {
        Some(Stop::Budget) => {
            format!(" within the work budget of {WORK_BUDGET} units (at {bits} bits)")
        }
        _ => format!(" at the {bits}-bit limit"),
    }
}

/// The note for a value printed as `decimal` under a request for `n`
/// significant digits, if it needs one.
pub fn note(decimal: &Decimal, n: usize) -> Option<String> {
    match decimal {
        Decimal::Digits {
            exact: true, text, ..
        } if text == "0" => Some("exactly 0: zero has no significant digits".into()),
        Decimal::Digits { exact: true, .. } => None,
        Decimal::Digits { digits, .. } if *digits < n => {
            Some(format!("{digits} of the {n} digits proved"))
        }
        Decimal::Digits { .. } => None,
        Decimal::Small { bound } => Some(format!(
            "no significant digit proved: |value| ≤ {bound}, not decided whether zero"
        )),
        Decimal::Range { .. } | Decimal::Undefined(_) => Some("no significant digit proved".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shortfall_is_named() {
        let digits = |text: &str, digits, exact| Decimal::Digits {
            text: text.into(),
            digits,
            exact,
        };
        assert_eq!(note(&digits("1.2346e-20", 5, false), 5), None);
        assert_eq!(note(&digits("2.5e-1", 2, true), 5), None);
        assert!(
            note(&digits("0", 1, true), 5)
                .unwrap()
                .contains("exactly 0")
        );
        assert!(
            note(&digits("1.2e-3", 2, false), 5)
                .unwrap()
                .contains("2 of the 5")
        );
        let small = Decimal::Small {
            bound: "2.2e-19".into(),
        };
        assert!(note(&small, 5).unwrap().contains("≤ 2.2e-19"));
    }
}
