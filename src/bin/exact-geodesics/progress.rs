//! A progress bar on a terminal, nothing when stderr is piped.

use exact_geodesics::degeneracy::CorpusProgress;
use exact_geodesics::mmp::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// A bar of `len` steps drawn with `template`; hidden unless stderr is a terminal.
fn hidden_unless_terminal(len: u64, template: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(
        Some(len),
        if std::io::stderr().is_terminal() {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        },
    );
    bar.set_style(
        ProgressStyle::with_template(template)
            .expect("valid template")
            .progress_chars("=> "),
    );
    bar
}

/// A bar over the vertices reached.
pub fn bar(vertex_count: usize) -> ProgressBar {
    hidden_unless_terminal(
        vertex_count as u64,
        "{elapsed_precise} [{bar:40}] {pos}/{len} vertices, front {msg}",
    )
}

/// A bar over the rows of a distance matrix.
pub fn row_bar(rows: usize) -> ProgressBar {
    hidden_unless_terminal(
        rows as u64,
        "{elapsed_precise} [{bar:40}] {pos}/{len} rows, {per_sec}, {eta} left",
    )
}

/// A bar over the vertices reached, headed by `label` (the model, backend and source).
pub fn labelled_bar(vertex_count: usize, label: String) -> ProgressBar {
    let bar = hidden_unless_terminal(
        vertex_count as u64,
        "{prefix} {elapsed_precise} [{bar:40}] {pos}/{len} vertices, front {msg}",
    );
    bar.set_prefix(label);
    bar
}

/// Feeds an engine progress report into the bar.
pub fn update(bar: &ProgressBar, p: &Progress) {
    bar.set_position(p.vertices_reached as u64);
    bar.set_message(format!("{:.4}", p.front));
}

/// A bar over the cases of a corpus run.
pub fn case_bar(cases: u64) -> ProgressBar {
    hidden_unless_terminal(
        cases,
        "{elapsed_precise} [{bar:40}] {pos}/{len} cases, {msg} with violations",
    )
}

/// Feeds a corpus progress report into the bar.
pub fn update_cases(bar: &ProgressBar, p: &CorpusProgress) {
    bar.set_position(p.done);
    bar.set_message(p.failing.to_string());
}
