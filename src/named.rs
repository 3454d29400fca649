//! Enums chosen by name on the command line, in JSON and in scene files.
//!
//! [`named_enum!`] writes such an enum once: its variants with their names, the
//! `ALL` list in declaration order, `name` and its inverse `from_name`. Every
//! named choice of the crate (shading models, shading modes, atmospheres, mesh
//! kinds) is declared through it, so a name and its parser cannot drift apart.

/// Declares a field-less enum whose every variant has a name.
///
/// ```text
/// named_enum! {
///     /// docs
///     pub enum Kind { /// docs
///                     Variant => "variant-name", … }
/// }
/// ```
///
/// Generates `Kind::ALL` (every variant, in declaration order), `Kind::name(self)`
/// and `Kind::from_name(&str) -> Option<Kind>` (`None` for an unknown name; names
/// are matched exactly, case included). The enum derives `Clone, Copy, Debug,
/// PartialEq, Eq`.
macro_rules! named_enum {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident {
            $( $(#[$vmeta:meta])* $variant:ident => $label:literal ),+ $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        $vis enum $name {
            $( $(#[$vmeta])* $variant ),+
        }

        impl $name {
            /// Every variant, in declaration order (the order tables and listings print).
            pub const ALL: [$name; [$(stringify!($variant)),+].len()] = [$($name::$variant),+];

            /// The name used on the command line, in JSON and in scene files.
            pub fn name(self) -> &'static str {
                match self {
                    $( $name::$variant => $label ),+
                }
            }

            /// Parse a name as `name` prints it; `None` if unknown.
            pub fn from_name(name: &str) -> Option<$name> {
                $name::ALL.into_iter().find(|v| v.name() == name)
            }
        }
    };
}

pub(crate) use named_enum;

#[cfg(test)]
mod tests {
    named_enum! {
        /// A test enum.
        enum Pick {
            /// First.
            One => "one",
            /// Second.
            TwoWords => "two-words",
        }
    }

    #[test]
    fn names_round_trip_and_unknown_is_none() {
        assert_eq!(Pick::ALL, [Pick::One, Pick::TwoWords]);
        for p in Pick::ALL {
            assert_eq!(Pick::from_name(p.name()), Some(p));
        }
        assert_eq!(Pick::TwoWords.name(), "two-words");
        assert_eq!(Pick::from_name("One"), None);
        assert_eq!(Pick::from_name(""), None);
    }
}
