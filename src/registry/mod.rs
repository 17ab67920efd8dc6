//! Every rule's identity: its code, name, severity and documentation, one
//! file a rule (the syntax errors share one). The rules raised below the
//! linter (the parser's `S...`, the CYCLE600 walk's and the rewrite's `C6..`)
//! are defined here, so that `syntax`, `semantic` and `emit` build their
//! diagnostics from the one definition (`RULE.at(span)`) that `sinuprep rule`
//! prints; the `N...` rules live with their checkers in `lint::rules`.

pub mod axis_beyond_limit;
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
pub mod cycle600_rewritable;
pub mod cycle600_shares_block;
pub mod cycle600_split_over_table;
pub mod cycle600_unknown_argument;
pub mod cycle600_unknown_head;
pub mod head_def_missing;
pub mod hirth_rounding;
pub mod invalid_swivel_data;
pub mod runtime_name_collision;
pub mod swivel_direction_outside_limits;
pub mod swivel_unreachable;
pub mod syntax;
pub mod undefined_swivel_record;
pub mod unreadable_machine_data;

use crate::diagnostic::RuleInfo;

/// The rules defined here, in code order.
pub static ALL: &[&RuleInfo] = &[
    &cycle600_argument_count::RULE,
    &cycle600_invalid_sequence_code::RULE,
    &cycle600_flag_not_boolean::RULE,
    &cycle600_unknown_head::RULE,
    &cycle600_unknown_argument::RULE,
    &cycle600_gimbal_lock::RULE,
    &cycle600_reserved_not_zero::RULE,
    &cycle600_additive_extrinsic_unknown_active::RULE,
    &cycle600_invalid_argument::RULE,
    &head_def_missing::RULE,
    &cycle600_no_cycle800_form::RULE,
    &runtime_name_collision::RULE,
    &cycle600_computed_at_run_time::RULE,
    &cycle600_shares_block::RULE,
    &cycle600_frames_over_programmable_frame::RULE,
    &cycle600_nested_too_deep::RULE,
    &cycle600_rewritable::RULE,
    &cycle600_split_over_table::RULE,
    &invalid_swivel_data::RULE,
    &swivel_unreachable::RULE,
    &swivel_direction_outside_limits::RULE,
    &hirth_rounding::RULE,
    &undefined_swivel_record::RULE,
    &unreadable_machine_data::RULE,
    &axis_beyond_limit::RULE,
    &syntax::UNCLOSED_STRING,
    &syntax::UNBALANCED_BRACKET,
    &syntax::INVALID_NUMBER,
    &syntax::UNKNOWN_CHARACTER,
    &syntax::UNEXPECTED_TOKEN,
    &syntax::MISSING_VALUE,
    &syntax::CONTINUED_BLOCK,
    &syntax::NESTING_TOO_DEEP,
    &syntax::TOO_LONG_TO_READ,
    &syntax::RECURSIVE_MACRO,
    &syntax::MACRO_REDEFINES_KEYWORD,
];
