//! Enums a request names by one fixed word: formats, languages, views,
//! layouts, what to do at a limit.
//!
//! The engine's crates carry no command-line library (the layers below the
//! service build without clap), so the CLI and the schema read a value's
//! spelling from here: one list of values and one name each, the same words
//! serde uses. The CLI turns a [`Choice`] into a clap value parser; the
//! request validator parses with [`Choice::from_name`].

/// An enum whose values a request names by a fixed word.
///
/// `name` must agree with the type's serde spelling, so that the JSON body,
/// the URL query, the command line and the cache key use one word per value
/// (`choice_names_are_serde_names` in each implementing module checks it).
pub trait Choice: Copy + Sized + Send + Sync + 'static {
    /// Every value, in the order they are listed in help text and errors.
    const ALL: &'static [Self];

    /// The value's request name.
    fn name(self) -> &'static str;

    /// The value a request name stands for, if any.
    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|v| v.name() == name)
    }

    /// Every request name, in [`Choice::ALL`] order.
    fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|v| v.name()).collect()
    }
}

/// Implements [`Choice`] for an enum from `Variant => "name"` pairs.
#[macro_export]
macro_rules! choice {
    ($ty:ty { $($variant:ident => $name:literal),+ $(,)? }) => {
        impl $crate::core::choice::Choice for $ty {
            const ALL: &'static [Self] = &[$(<$ty>::$variant),+];
            fn name(self) -> &'static str {
                match self { $(<$ty>::$variant => $name),+ }
            }
        }
    };
}
