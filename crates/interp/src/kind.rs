//! Which interpolation scheme of thesis 4.3, and whether as printed or
//! corrected.

use std::fmt;
use std::str::FromStr;

use crate::InterpError;

/// The continuity scheme of a section of 4.3.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Scheme {
    C1,
    C2,
    G1,
    G2,
}

impl Scheme {
    pub const ALL: [Scheme; 4] = [Scheme::C1, Scheme::C2, Scheme::G1, Scheme::G2];

    /// Where the thesis prints it.
    pub fn source(&self) -> &'static str {
        match self {
            Scheme::C1 => "thesis 4.3.1, (4.19)–(4.21)",
            Scheme::C2 => "thesis 4.3.2, (4.22)–(4.25)",
            Scheme::G1 => "thesis 4.3.3, (4.26)–(4.27)",
            Scheme::G2 => "thesis 4.3.4, (4.28)–(4.34)",
        }
    }

    /// The corrected variant of a print that has one (the C² and G²
    /// schemes), as the evidence names it; `None` where the printed scheme
    /// is the corrected one.
    pub fn correction(&self) -> Option<&'static str> {
        match self {
            Scheme::C1 | Scheme::G1 => None,
            Scheme::C2 => Some("interior d_i from the C² conditions"),
            Scheme::G2 => Some("join (4.33) solved in x through the basis, each piece its own m_i"),
        }
    }
}

impl fmt::Display for Scheme {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Scheme::C1 => "c1",
            Scheme::C2 => "c2",
            Scheme::G1 => "g1",
            Scheme::G2 => "g2",
        })
    }
}

impl FromStr for Scheme {
    type Err = InterpError;
    fn from_str(s: &str) -> Result<Self, InterpError> {
        Scheme::ALL
            .into_iter()
            .find(|k| k.to_string().eq_ignore_ascii_case(s))
            .ok_or_else(|| InterpError::UnknownScheme(s.to_string()))
    }
}

/// As printed, or corrected (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Variant {
    Printed,
    Corrected,
}

impl fmt::Display for Variant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Variant::Printed => "printed",
            Variant::Corrected => "corrected",
        })
    }
}
