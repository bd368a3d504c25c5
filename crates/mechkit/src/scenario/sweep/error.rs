//! What can go wrong in a sweep.

use crate::scenario::ScenarioError;

/// An error in a sweep's parameters, one of its runs, or the parts to merge.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// A `--set` text that cannot be read.
    #[error("--set \"{text}\": {reason}\n  = hint: {hint}")]
    BadSet {
        /// As given.
        text: String,
        /// What is wrong.
        reason: String,
        /// What would fix it.
        hint: String,
    },
    /// The same parameter set twice.
    #[error(
        "--set gives `{name}` twice\n  = hint: give each constant one --set (a list: `{name}=1,2,4`)"
    )]
    Duplicate {
        /// The constant.
        name: String,
    },
    /// Options that do not fit (no --set, --random 0, a --plot that is not a plot of the
    /// scenario).
    #[error("{0}")]
    Options(String),
    /// A `--shard` text that cannot be read.
    #[error("--shard \"{text}\": {reason}\n  = hint: write K/N with 1 <= K <= N, e.g. --shard 2/8")]
    BadShard {
        /// As given.
        text: String,
        /// What is wrong.
        reason: String,
    },
    /// The scenario (with the sweep's values) is not valid.
    #[error("{source}")]
    Scenario {
        /// The scenario's error.
        source: ScenarioError,
    },
    /// One run's scenario or run failed before it could give a row.
    #[error("run {index} ({values}): {source}")]
    Run {
        /// The run's index.
        index: usize,
        /// Its parameter values, `v0=1, k=2`.
        values: String,
        /// The scenario's error.
        source: ScenarioError,
    },
    /// A part to merge that is not a sweep table.
    #[error(
        "{file}: {reason}\n  = hint: give the sweep.partK.csv files that `mechkit sweep --shard K/N` wrote"
    )]
    NotATable {
        /// The file.
        file: String,
        /// What is wrong.
        reason: String,
    },
    /// Parts of different sweeps.
    #[error(
        "{file} is from another sweep than {first}: {what} differs\n  = hint: merge only the parts of one sweep (same scenario text, same --set, same sampling)"
    )]
    Mismatch {
        /// The first part.
        first: String,
        /// The part that differs.
        file: String,
        /// Which line differs.
        what: String,
    },
    /// Runs given twice, or missing.
    #[error("{0}")]
    Coverage(String),
    /// Bytes that are not a sweep's part ([`super::SweepTable::from_bytes`]): damaged, or
    /// written by another version of mechkit.
    #[error("{0}")]
    BadPart(String),
}
