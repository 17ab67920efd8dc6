//! Every rule: one file each, registered here in code order.

pub mod argument_count_mismatch;
pub mod block_after_program_end;
pub mod block_numbers_backwards;
pub mod block_too_long;
pub mod call_shares_block;
pub mod cycle600_results_without_stopre;
pub mod cycle800_arguments;
pub mod cycle800_fed_extrinsic;
pub mod def_after_executable;
pub mod duplicate_def;
pub mod duplicate_label;
pub mod empty_program;
pub mod g_group_conflict;
pub mod identifier_too_long;
pub mod incomplete_circle;
pub mod inconsistent_case;
pub mod jump_direction;
pub mod m_group_conflict;
pub mod main_run_read_without_stopre;
pub mod missing_feed_rate;
pub mod missing_program_end;
pub mod modal_state_at_end;
pub mod plane_change_with_radius_compensation;
pub mod proc_name_mismatch;
pub mod repeated_address;
pub mod spindle_not_started;
pub mod support;
pub mod too_many_m_functions;
pub mod transformation_with_radius_compensation;
pub mod traori_at_end;
pub mod unclosed_block;
pub mod undefined_label;
pub mod undefined_variable;
pub mod unused_suppression;
pub mod unused_variable;

use crate::lint::rule::{Check, EachBlock, FromStart, InLineOrder, Rule};

fn checker<C: Check + Default + 'static>() -> Box<dyn Check> {
    Box::new(C::default())
}

/// All rules, sorted by code: the linter's own and those of the [`crate::registry`].
pub fn all() -> Vec<Rule> {
    let mut rules = vec![
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
            info: &call_shares_block::RULE,
            checker: Some(checker::<call_shares_block::Checker>),
        },
        Rule {
            info: &empty_program::RULE,
            checker: Some(checker::<empty_program::Checker>),
        },
        Rule {
            info: &too_many_m_functions::RULE,
            checker: Some(checker::<too_many_m_functions::Checker>),
        },
        Rule {
            info: &repeated_address::RULE,
            checker: Some(checker::<EachBlock<repeated_address::Checker>>),
        },
        Rule {
            info: &g_group_conflict::RULE,
            checker: Some(checker::<EachBlock<g_group_conflict::Checker>>),
        },
        Rule {
            info: &m_group_conflict::RULE,
            checker: Some(checker::<EachBlock<m_group_conflict::Checker>>),
        },
        Rule {
            info: &incomplete_circle::RULE,
            checker: Some(checker::<incomplete_circle::Checker>),
        },
        Rule {
            info: &missing_feed_rate::RULE,
            checker: Some(checker::<FromStart<missing_feed_rate::Checker>>),
        },
        Rule {
            info: &block_after_program_end::RULE,
            checker: Some(checker::<block_after_program_end::Checker>),
        },
        Rule {
            info: &transformation_with_radius_compensation::RULE,
            checker: Some(checker::<InLineOrder<transformation_with_radius_compensation::Checker>>),
        },
        Rule {
            info: &plane_change_with_radius_compensation::RULE,
            checker: Some(checker::<InLineOrder<plane_change_with_radius_compensation::Checker>>),
        },
        Rule {
            info: &modal_state_at_end::RULE,
            checker: Some(checker::<InLineOrder<modal_state_at_end::Checker>>),
        },
        Rule {
            info: &spindle_not_started::RULE,
            checker: Some(checker::<FromStart<spindle_not_started::Checker>>),
        },
        Rule {
            info: &cycle600_results_without_stopre::RULE,
            checker: Some(checker::<cycle600_results_without_stopre::Checker>),
        },
        Rule {
            info: &cycle800_fed_extrinsic::RULE,
            checker: Some(checker::<cycle800_fed_extrinsic::Checker>),
        },
    ];
    rules.extend(crate::registry::ALL.iter().map(|&info| Rule {
        info,
        checker: None,
    }));
    rules.sort_by_key(|r| r.info.code);
    rules
}
