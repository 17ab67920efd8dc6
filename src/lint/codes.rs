//! Rule codes as users write them (`--select`, `--ignore`, `select` and
//! `ignore` in sinuprep.toml, suppression comments): case-insensitive and
//! trimmed, and each one a rule's code or a prefix of one, since a code that
//! matches nothing would silently select or suppress nothing.

use crate::lint::rules;

/// A code that names no rule, and the nearest one that does.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownCode {
    pub code: String,
    pub did_you_mean: Option<&'static str>,
}

/// `codes` in upper case without blanks, every one checked.
pub fn normalize(codes: &[String]) -> Result<Vec<String>, UnknownCode> {
    codes
        .iter()
        .map(|code| code.trim().to_ascii_uppercase())
        .filter(|code| !code.is_empty())
        .map(|code| check(&code).map(|()| code))
        .collect()
}

/// Whether `code` (upper case) is a rule's code or a prefix of one.
pub fn check(code: &str) -> Result<(), UnknownCode> {
    let all = rules::all();
    if all.iter().any(|r| r.info.code.starts_with(code)) {
        return Ok(());
    }
    let codes: Vec<&'static str> = all.iter().map(|r| r.info.code).collect();
    Err(UnknownCode {
        code: code.to_string(),
        did_you_mean: crate::suggest::closest(code, &codes, 2).copied(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_trimmed_case_free_and_checked() {
        let given = [" n016".to_string(), "N005 ".to_string(), "c6".to_string()];
        assert_eq!(
            normalize(&given),
            Ok(vec!["N016".into(), "N005".into(), "C6".into()])
        );
        let wrong = normalize(&["N05".to_string()]).expect_err("no rule");
        assert_eq!(wrong.code, "N05");
        assert_eq!(wrong.did_you_mean, Some("N005"));
        assert!(normalize(&["X1".to_string()]).is_err());
    }
}
