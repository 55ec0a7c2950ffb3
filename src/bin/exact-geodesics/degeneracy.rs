//! `degeneracy`: runs the degenerate-mesh corpus in one backend and reports every broken
//! invariant, as JSON; fails if there is any.

use crate::{emit, progress, Backend};
use clap::Args;
use exact_geodesics::degeneracy::run_corpus;
use std::path::PathBuf;

#[derive(Args)]
pub struct DegeneracyArgs {
    /// Number type of the engine under test (f64 is checked against adaptive, the others
    /// against f64; exact runs on meshes of at most 100 faces).
    #[arg(long, value_enum, default_value_t = Backend::F64)]
    backend: Backend,
    /// Number of cases, cycling through the kinds of degeneracy.
    #[arg(long, default_value_t = 1000)]
    cases: u64,
    /// Seed of the corpus.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Write the summary to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &DegeneracyArgs) -> Result<(), String> {
    let bar = progress::case_bar(args.cases);
    // A panic is one counted violation with its message; the default hook would also print it
    // over the progress bar.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let summary = run_corpus(args.backend.into(), args.cases, args.seed, |p| {
        progress::update_cases(&bar, p)
    });
    std::panic::set_hook(hook);
    bar.finish_and_clear();
    let mut text = serde_json::to_string_pretty(&summary).expect("JSON of plain values");
    text.push('\n');
    emit(args.out.as_ref(), &text)?;
    match summary.cases_with_violations {
        0 => Ok(()),
        n => Err(format!(
            "{n} of {} cases broke an invariant in the {} backend",
            summary.cases,
            args.backend.name()
        )),
    }
}
