//! A progress bar on a terminal, nothing when stderr is piped.

use exact_geodesics::mmp::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// A bar over the vertices reached; hidden unless stderr is a terminal.
pub fn bar(vertex_count: usize) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(
        Some(vertex_count as u64),
        if std::io::stderr().is_terminal() {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        },
    );
    bar.set_style(
        ProgressStyle::with_template(
            "{elapsed_precise} [{bar:40}] {pos}/{len} vertices, front {msg}",
        )
        .expect("valid template")
        .progress_chars("=> "),
    );
    bar
}

/// Feeds an engine progress report into the bar.
pub fn update(bar: &ProgressBar, p: &Progress) {
    bar.set_position(p.vertices_reached as u64);
    bar.set_message(format!("{:.4}", p.front));
}
