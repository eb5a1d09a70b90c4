//! Wall-clock time per pipeline stage, for the summary line, logs and
//! benchmarks. Timing never changes output: it is only reported.

use std::time::{Duration, Instant};

/// How long each pipeline stage took.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PhaseTimes {
    /// Parsing and parameter binding.
    pub parse: Duration,
    /// Evaluation (rule expansion) into a model.
    pub eval: Duration,
    /// Tessellation and merging into meshes (and printing).
    pub mesh: Duration,
    /// Encoding the output bytes.
    pub export: Duration,
}

/// A pipeline stage, the slot of [`PhaseTimes`] a lap is recorded in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// [`PhaseTimes::parse`].
    Parse,
    /// [`PhaseTimes::eval`].
    Eval,
    /// [`PhaseTimes::mesh`].
    Mesh,
    /// [`PhaseTimes::export`].
    Export,
}

/// Times the stages of one render: each [`StageClock::lap`] records the
/// time since the previous one. The pipeline owns it; a front end laps
/// [`Phase::Parse`] between parsing and evaluating, which only it can tell apart.
#[derive(Debug)]
pub struct StageClock {
    /// The times recorded so far.
    pub phases: PhaseTimes,
    mark: Instant,
}

impl StageClock {
    /// Starts timing now.
    pub fn start() -> StageClock {
        StageClock { phases: PhaseTimes::default(), mark: Instant::now() }
    }

    /// Records the time since the last lap as `phase`'s.
    pub fn lap(&mut self, phase: Phase) {
        let slot = match phase {
            Phase::Parse => &mut self.phases.parse,
            Phase::Eval => &mut self.phases.eval,
            Phase::Mesh => &mut self.phases.mesh,
            Phase::Export => &mut self.phases.export,
        };
        *slot = self.mark.elapsed();
        self.mark = Instant::now();
    }
}
