//! Every rule: one file each, registered here in code order.

pub mod argument_count_mismatch;
pub mod block_numbers_backwards;
pub mod block_too_long;
pub mod cycle600_additive_extrinsic_unknown_active;
pub mod cycle600_argument_count;
pub mod cycle600_computed_at_run_time;
pub mod cycle600_flag_not_boolean;
pub mod cycle600_frames_over_programmable_frame;
pub mod cycle600_gimbal_lock;
pub mod cycle600_invalid_argument;
pub mod cycle600_invalid_sequence_code;
pub mod cycle600_nested_too_deep;
pub mod cycle600_no_cycle800_form;
pub mod cycle600_reserved_not_zero;
pub mod cycle600_results_without_stopre;
pub mod cycle600_shares_block;
pub mod cycle600_unknown_argument;
pub mod cycle600_unknown_head;
pub mod cycle800_arguments;
pub mod cycle800_fed_extrinsic;
pub mod def_after_executable;
pub mod duplicate_def;
pub mod duplicate_label;
pub mod head_def_missing;
pub mod identifier_too_long;
pub mod inconsistent_case;
pub mod jump_direction;
pub mod main_run_read_without_stopre;
pub mod missing_program_end;
pub mod proc_name_mismatch;
pub mod runtime_name_collision;
pub mod support;
pub mod syntax_errors;
pub mod traori_at_end;
pub mod unclosed_block;
pub mod undefined_label;
pub mod undefined_variable;
pub mod unused_suppression;
pub mod unused_variable;

use crate::lint::rule::{Check, Rule};

fn checker<C: Check + Default + 'static>() -> Box<dyn Check> {
    Box::new(C::default())
}

/// All rules, sorted by code.
pub fn all() -> Vec<Rule> {
    let mut rules = vec![
        Rule {
            info: &syntax_errors::UNCLOSED_STRING,
            checker: None,
        },
        Rule {
            info: &syntax_errors::UNBALANCED_BRACKET,
            checker: None,
        },
        Rule {
            info: &syntax_errors::INVALID_NUMBER,
            checker: None,
        },
        Rule {
            info: &syntax_errors::UNKNOWN_CHARACTER,
            checker: None,
        },
        Rule {
            info: &syntax_errors::UNEXPECTED_TOKEN,
            checker: None,
        },
        Rule {
            info: &syntax_errors::MISSING_VALUE,
            checker: None,
        },
        Rule {
            info: &syntax_errors::CONTINUED_BLOCK,
            checker: None,
        },
        Rule {
            info: &syntax_errors::NESTING_TOO_DEEP,
            checker: None,
        },
        Rule {
            info: &syntax_errors::TOO_LONG_TO_READ,
            checker: None,
        },
        Rule {
            info: &cycle600_argument_count::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_invalid_sequence_code::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_flag_not_boolean::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_unknown_head::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_unknown_argument::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_gimbal_lock::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_reserved_not_zero::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_additive_extrinsic_unknown_active::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_invalid_argument::RULE,
            checker: None,
        },
        Rule {
            info: &head_def_missing::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_no_cycle800_form::RULE,
            checker: None,
        },
        Rule {
            info: &runtime_name_collision::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_computed_at_run_time::RULE,
            checker: None,
        },
        Rule {
            info: &unused_suppression::RULE,
            checker: None,
        },
        Rule {
            info: &undefined_label::RULE,
            checker: Some(checker::<undefined_label::Checker>),
        },
        Rule {
            info: &jump_direction::RULE,
            checker: Some(checker::<jump_direction::Checker>),
        },
        Rule {
            info: &duplicate_label::RULE,
            checker: Some(checker::<duplicate_label::Checker>),
        },
        Rule {
            info: &unclosed_block::RULE,
            checker: Some(checker::<unclosed_block::Checker>),
        },
        Rule {
            info: &undefined_variable::RULE,
            checker: Some(checker::<undefined_variable::Checker>),
        },
        Rule {
            info: &def_after_executable::RULE,
            checker: Some(checker::<def_after_executable::Checker>),
        },
        Rule {
            info: &duplicate_def::RULE,
            checker: Some(checker::<duplicate_def::Checker>),
        },
        Rule {
            info: &block_too_long::RULE,
            checker: Some(checker::<block_too_long::Checker>),
        },
        Rule {
            info: &cycle800_arguments::RULE,
            checker: Some(checker::<cycle800_arguments::Checker>),
        },
        Rule {
            info: &missing_program_end::RULE,
            checker: Some(checker::<missing_program_end::Checker>),
        },
        Rule {
            info: &identifier_too_long::RULE,
            checker: Some(checker::<identifier_too_long::Checker>),
        },
        Rule {
            info: &traori_at_end::RULE,
            checker: Some(checker::<traori_at_end::Checker>),
        },
        Rule {
            info: &main_run_read_without_stopre::RULE,
            checker: Some(checker::<main_run_read_without_stopre::Checker>),
        },
        Rule {
            info: &block_numbers_backwards::RULE,
            checker: Some(checker::<block_numbers_backwards::Checker>),
        },
        Rule {
            info: &inconsistent_case::RULE,
            checker: Some(checker::<inconsistent_case::Checker>),
        },
        Rule {
            info: &unused_variable::RULE,
            checker: Some(checker::<unused_variable::Checker>),
        },
        Rule {
            info: &proc_name_mismatch::RULE,
            checker: Some(checker::<proc_name_mismatch::Checker>),
        },
        Rule {
            info: &argument_count_mismatch::RULE,
            checker: Some(checker::<argument_count_mismatch::Checker>),
        },
        Rule {
            info: &cycle600_results_without_stopre::RULE,
            checker: Some(checker::<cycle600_results_without_stopre::Checker>),
        },
        Rule {
            info: &cycle800_fed_extrinsic::RULE,
            checker: Some(checker::<cycle800_fed_extrinsic::Checker>),
        },
        Rule {
            info: &cycle600_shares_block::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_frames_over_programmable_frame::RULE,
            checker: None,
        },
        Rule {
            info: &cycle600_nested_too_deep::RULE,
            checker: None,
        },
    ];
    rules.sort_by_key(|r| r.info.code);
    rules
}
