//! Where a result came from: enough to run it again and get the same bits.

use serde::Serialize;

use crate::Real;
use crate::ode::Tolerance;
use crate::simulate::{RunReport, Stepping};

/// The provenance block of a summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Provenance {
    /// mechkit's version.
    pub mechkit: &'static str,
    /// FNV-1a (64 bits, hex) of the scenario text: tells different inputs apart (not a
    /// security hash).
    pub scenario_fnv1a: String,
    /// Integration method.
    pub method: String,
    /// The fixed step (s), for fixed-step runs.
    pub dt: Option<Real>,
    /// Relative tolerance of an adaptive run (`null` when given per component).
    pub rtol: Option<Real>,
    /// Absolute tolerance of an adaptive run (`null` when given per component).
    pub atol: Option<Real>,
    /// Random seed: `null`, a scenario run draws no random numbers.
    pub seed: Option<u64>,
    /// Threads the run used: 1 (a run is sequential; sweeps run whole runs in parallel, each
    /// the same bits on any number of threads).
    pub threads: usize,
    /// Whether formulas ran as native code (`MECHKIT_JIT=0` runs the interpreter, which
    /// gives the same bits).
    pub native_code: bool,
    /// Target architecture and operating system.
    pub platform: String,
}

impl Provenance {
    /// The provenance of `report`, a run of the scenario text hashed as `source_hash`.
    pub(crate) fn of(report: &RunReport, source_hash: u64) -> Provenance {
        let scalar = |t: &Tolerance| match t {
            Tolerance::Scalar(x) => Some(*x),
            Tolerance::PerComponent(_) => None,
        };
        let (dt, rtol, atol) = match &report.stepping {
            Stepping::Fixed { dt, .. } => (Some(*dt), None, None),
            Stepping::Adaptive { config, .. } => (None, scalar(&config.rtol), scalar(&config.atol)),
        };
        Provenance {
            mechkit: env!("CARGO_PKG_VERSION"),
            scenario_fnv1a: format!("{source_hash:016x}"),
            method: report.method.name().to_string(),
            dt,
            rtol,
            atol,
            seed: None,
            threads: 1,
            native_code: mechkit_expr::native_code(),
            platform: format!("{}-{}", std::env::consts::ARCH, std::env::consts::OS),
        }
    }
}

/// FNV-1a, 64 bits.
pub(crate) fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}
