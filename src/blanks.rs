//! Sentences with `{}` blanks, filled in order: the one filler behind the translated
//! sentences of the command line (`crate::i18n::catalog::tr_fill`, and `checker::texts::tr_fill`
//! for the checker, which builds without the PO files too).

/// `template` with each `{}` replaced by the next of `args`, in order. Blanks beyond the
/// arguments stay `{}`; arguments beyond the blanks are ignored.
///
/// ```
/// assert_eq!(lightlab::blanks::fill("{} of {} cases", &["3", "10"]), "3 of 10 cases");
/// assert_eq!(lightlab::blanks::fill("{} and {}", &["a"]), "a and {}");
/// ```
#[must_use]
pub fn fill(template: &str, args: &[&str]) -> String {
    let mut out = String::with_capacity(template.len());
    let mut rest = template;
    let mut args = args.iter();
    while let Some(at) = rest.find("{}") {
        out.push_str(&rest[..at]);
        match args.next() {
            Some(a) => out.push_str(a),
            None => out.push_str("{}"),
        }
        rest = &rest[at + 2..];
    }
    out.push_str(rest);
    out
}
