//! Echoing user input in messages: bounded and on one line.
//!
//! An error quotes what the user typed so they can find it, but input can be
//! arbitrarily long (a 1 GiB argument or file) or contain line breaks. Every
//! echo goes through [`echo`]: control characters are escaped and anything
//! beyond [`MAX_ECHO`] characters is cut, with the full length stated.

/// Longest echoed input, in characters.
pub const MAX_ECHO: usize = 60;

/// `text` with its control characters (line breaks, tabs, …) escaped.
pub fn escape_controls(text: &str) -> String {
    text.chars()
        .flat_map(|c| {
            if c.is_control() {
                c.escape_default().collect::<Vec<_>>()
            } else {
                vec![c]
            }
        })
        .collect()
}

/// `input` on one line, at most [`MAX_ECHO`] characters of it.
pub fn echo(input: &str) -> String {
    let count = input.chars().count();
    let head: String = input.chars().take(MAX_ECHO).collect();
    let shown = escape_controls(&head);
    if count > MAX_ECHO {
        format!("{shown}… ({count} characters)")
    } else {
        shown
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_and_multiline_input_is_cut_and_escaped() {
        assert_eq!(echo("0.6"), "0.6");
        assert_eq!(echo("1\n2"), "1\\n2");
        let long = "7".repeat(1000);
        let e = echo(&long);
        assert!(e.ends_with("… (1000 characters)"), "{e}");
        assert!(e.chars().count() < 100);
    }
}
