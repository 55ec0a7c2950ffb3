//! `subdivision`: the 2D subdivision of one face [LZT Property 4, Fig. 15], as a region list and
//! optionally an SVG drawing.

use crate::{emit, with_backend, Backend, Common};
use clap::Args;
use exact_geodesics::paper::subdivision_summary;
use exact_geodesics::render::svg::subdivision_svg;
use exact_geodesics::subdivision::face_subdivision;
use exact_geodesics::FaceId;
use std::path::PathBuf;

#[derive(Args)]
pub struct SubdivisionArgs {
    #[command(flatten)]
    common: Common,
    /// The face to subdivide.
    #[arg(long, value_name = "F")]
    face: u32,
    /// Also draw the subdivision into this SVG file.
    #[arg(long, value_name = "OUT.svg")]
    svg: Option<PathBuf>,
    /// Write the region list to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &SubdivisionArgs) -> Result<(), String> {
    let job = args.common.job()?;
    if args.face as usize >= job.mesh.face_count() {
        return Err(format!(
            "--face {f}: face {f} is out of range: {} has {} faces",
            args.common.mesh,
            job.mesh.face_count(),
            f = args.face,
        ));
    }
    let subdivision = with_backend!(job.backend, S => {
        let field = job.field::<S>()?;
        face_subdivision(&field, FaceId(args.face))
    });
    if let Some(path) = &args.svg {
        std::fs::write(path, subdivision_svg(&subdivision))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    emit(args.out.as_ref(), &subdivision_summary(&subdivision))
}
