//! Wall-clock time per pipeline stage, for the summary line, logs, the
//! service's `Server-Timing` header, its per-stage histograms and trace
//! spans, and benchmarks. Timing never changes output: it is only reported.

use std::time::{Duration, Instant};

/// How long each pipeline stage took, and which stages ran.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PhaseTimes {
    /// Parsing and parameter binding.
    pub parse: Duration,
    /// Evaluation (rule expansion) into a model.
    pub eval: Duration,
    /// Uniting the parts into one printable solid (`print=true` only).
    pub print: Duration,
    /// Tessellation and merging into meshes (for printing: the parts).
    pub mesh: Duration,
    /// Drawing the preview picture (`format=png` only).
    pub preview: Duration,
    /// Encoding the output bytes.
    pub export: Duration,
    /// The stages lapped, in the order of [`Phase::ALL`] (a bit per phase):
    /// a stage that did not run is absent rather than 0 ms.
    ran: u8,
}

/// A pipeline stage, the slot of [`PhaseTimes`] a lap is recorded in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// [`PhaseTimes::parse`].
    Parse,
    /// [`PhaseTimes::eval`].
    Eval,
    /// [`PhaseTimes::print`].
    Print,
    /// [`PhaseTimes::mesh`].
    Mesh,
    /// [`PhaseTimes::preview`].
    Preview,
    /// [`PhaseTimes::export`].
    Export,
}

impl Phase {
    /// Every phase, in the order a render runs them (parse, eval, mesh, print, preview, export).
    pub const ALL: [Phase; 6] = [Phase::Parse, Phase::Eval, Phase::Mesh, Phase::Print, Phase::Preview, Phase::Export];

    /// The stage's short name, as in `Server-Timing` (`parse`, `eval`, `print`, `mesh`, `preview`, `export`)
    /// and the `stage` label of the metrics.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Parse => "parse",
            Phase::Eval => "eval",
            Phase::Print => "print",
            Phase::Mesh => "mesh",
            Phase::Preview => "preview",
            Phase::Export => "export",
        }
    }

    fn bit(self) -> u8 {
        match self {
            Phase::Parse => 1,
            Phase::Eval => 2,
            Phase::Print => 4,
            Phase::Mesh => 8,
            Phase::Export => 16,
            Phase::Preview => 32,
        }
    }
}

impl PhaseTimes {
    /// The time recorded for `phase` (zero when it did not run).
    pub fn get(&self, phase: Phase) -> Duration {
        match phase {
            Phase::Parse => self.parse,
            Phase::Eval => self.eval,
            Phase::Print => self.print,
            Phase::Mesh => self.mesh,
            Phase::Preview => self.preview,
            Phase::Export => self.export,
        }
    }

    /// Whether `phase` was lapped in this render.
    pub fn did_run(&self, phase: Phase) -> bool {
        self.ran & phase.bit() != 0
    }

    /// The stages that ran with their times, in running order. Laps are
    /// consecutive, so the times add up to at most the render's wall time.
    pub fn ran(&self) -> impl Iterator<Item = (Phase, Duration)> + '_ {
        Phase::ALL.into_iter().filter(|p| self.did_run(*p)).map(|p| (p, self.get(p)))
    }

    /// The sum of the stages' times.
    pub fn total(&self) -> Duration {
        self.ran().map(|(_, d)| d).sum()
    }
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

    /// Records the time since the last lap as `phase`'s (added to it, should
    /// a phase be lapped twice).
    pub fn lap(&mut self, phase: Phase) {
        let now = Instant::now();
        let took = now.saturating_duration_since(self.mark);
        let slot = match phase {
            Phase::Parse => &mut self.phases.parse,
            Phase::Eval => &mut self.phases.eval,
            Phase::Print => &mut self.phases.print,
            Phase::Mesh => &mut self.phases.mesh,
            Phase::Preview => &mut self.phases.preview,
            Phase::Export => &mut self.phases.export,
        };
        *slot = slot.saturating_add(took);
        self.phases.ran |= phase.bit();
        self.mark = now;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_lapped_stages_ran_and_they_add_up() {
        let started = Instant::now();
        let mut clock = StageClock::start();
        clock.lap(Phase::Parse);
        std::thread::sleep(Duration::from_millis(2));
        clock.lap(Phase::Eval);
        clock.lap(Phase::Export);
        let wall = started.elapsed();
        let ran: Vec<Phase> = clock.phases.ran().map(|(p, _)| p).collect();
        assert_eq!(ran, [Phase::Parse, Phase::Eval, Phase::Export]);
        assert!(!clock.phases.did_run(Phase::Mesh));
        assert!(clock.phases.eval >= Duration::from_millis(2));
        assert!(clock.phases.total() <= wall, "{:?} > {wall:?}", clock.phases.total());
    }
}
