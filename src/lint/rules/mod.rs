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

use crate::lint::rule::{AtEnd, Check, Checking, EachBlock, FromStart, ModalCheck, Rule};

fn checker<C: Check + Default + 'static>() -> Box<dyn Check> {
    Box::new(C::default())
}

fn modal_checker<C: ModalCheck + Default + 'static>() -> Box<dyn ModalCheck> {
    Box::new(C::default())
}

/// The rules of the modules named, each module's `Checker` its checker:
/// `in` names the checker that reads the program for it (`AtEnd`,
/// `EachBlock`, `FromStart`; `InLineOrder`, one for all its rules), `: none`
/// says that its findings come from elsewhere (the suppressions).
macro_rules! rules {
    ($($module:ident $(in $reader:ident)? $(: $none:ident)?,)*) => {
        vec![$(Rule {
            info: &$module::RULE,
            checking: rules!(@checking $module $($reader)? $(: $none)?),
        },)*]
    };
    (@checking $module:ident : none) => {
        Checking::Elsewhere
    };
    (@checking $module:ident InLineOrder) => {
        Checking::InLineOrder(modal_checker::<$module::Checker>)
    };
    (@checking $module:ident) => {
        Checking::Own(checker::<$module::Checker>)
    };
    (@checking $module:ident $reader:ident) => {
        Checking::Own(checker::<$reader<$module::Checker>>)
    };
}

/// All rules, sorted by code: the linter's own and those of the [`crate::registry`].
pub fn all() -> Vec<Rule> {
    let mut rules = rules![
        unused_suppression: none,
        undefined_label,
        jump_direction,
        duplicate_label,
        unclosed_block in AtEnd,
        undefined_variable,
        def_after_executable,
        duplicate_def in AtEnd,
        block_too_long,
        cycle800_arguments,
        missing_program_end,
        identifier_too_long,
        traori_at_end,
        main_run_read_without_stopre,
        block_numbers_backwards,
        inconsistent_case,
        unused_variable,
        proc_name_mismatch,
        argument_count_mismatch,
        call_shares_block,
        empty_program in AtEnd,
        too_many_m_functions,
        repeated_address in EachBlock,
        g_group_conflict in EachBlock,
        m_group_conflict in EachBlock,
        incomplete_circle,
        missing_feed_rate in FromStart,
        block_after_program_end,
        transformation_with_radius_compensation in InLineOrder,
        plane_change_with_radius_compensation in InLineOrder,
        modal_state_at_end in InLineOrder,
        spindle_not_started in FromStart,
        cycle600_results_without_stopre,
        cycle800_fed_extrinsic,
    ];
    rules.extend(crate::registry::ALL.iter().map(|&info| Rule {
        info,
        checking: Checking::Elsewhere,
    }));
    rules.sort_by_key(|r| r.info.code);
    rules
}
