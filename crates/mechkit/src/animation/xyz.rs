//! The animation of a many-particle run from its extended XYZ frames (`mechkit md
//! --xyz-every`, or any file with `Lattice="…"` and positions): the atoms as balls in the
//! box, seen along z, nearer atoms drawn over farther ones.

use super::{Animation, AnimationOptions, Colour, Frame, Geometry, Shape, View};
use crate::Real;

/// One frame of an extended XYZ file.
#[derive(Debug, Clone, PartialEq)]
pub struct XyzFrame {
    /// `Time=` of the comment line (0 when absent).
    pub time: Real,
    /// The box's edge lengths from `Lattice="…"` (its diagonal), if given.
    pub lattice: Option<[Real; 3]>,
    /// Each atom's position.
    pub positions: Vec<[Real; 3]>,
}

/// The most atoms an animation draws.
pub const MAX_ATOMS: usize = 20_000;

fn key_value<'a>(comment: &'a str, key: &str) -> Option<&'a str> {
    let start = comment.find(&format!("{key}="))? + key.len() + 1;
    let rest = &comment[start..];
    if let Some(quoted) = rest.strip_prefix('"') {
        quoted.split('"').next()
    } else {
        rest.split_whitespace().next()
    }
}

/// Reads the frames of an extended XYZ file; an error names the line.
///
/// # Errors
/// A count that is not a number, a frame shorter than its count, a position that is not
/// three numbers.
pub fn parse_xyz(text: &str) -> Result<Vec<XyzFrame>, String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut frames = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        if lines[i].trim().is_empty() {
            i += 1;
            continue;
        }
        let n: usize = lines[i]
            .trim()
            .parse()
            .map_err(|_| format!("line {}: `{}` is not an atom count", i + 1, lines[i].trim()))?;
        if n > MAX_ATOMS {
            return Err(format!(
                "line {}: {n} atoms; an animation draws at most {MAX_ATOMS}",
                i + 1
            ));
        }
        let comment = lines.get(i + 1).copied().unwrap_or_default();
        let time = key_value(comment, "Time")
            .and_then(|t| t.parse().ok())
            .unwrap_or(0.0);
        let lattice = key_value(comment, "Lattice").and_then(|l| {
            let v: Vec<Real> = l
                .split_whitespace()
                .filter_map(|x| x.parse().ok())
                .collect();
            (v.len() == 9).then(|| [v[0], v[4], v[8]])
        });
        let mut positions = Vec::with_capacity(n);
        for k in 0..n {
            let line_no = i + 2 + k;
            let line = lines.get(line_no).ok_or_else(|| {
                format!(
                    "line {}: the frame ends after {k} of its {n} atoms",
                    line_no + 1
                )
            })?;
            let mut fields = line.split_whitespace().skip(1);
            let mut p = [0.0; 3];
            for c in &mut p {
                *c = fields
                    .next()
                    .and_then(|x| x.parse::<Real>().ok())
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| {
                        format!(
                            "line {}: an atom line is a name and three numbers",
                            line_no + 1
                        )
                    })?;
            }
            positions.push(p);
        }
        frames.push(XyzFrame {
            time,
            lattice,
            positions,
        });
        i += 2 + n;
    }
    if frames.is_empty() {
        return Err("no frame: the file is empty".into());
    }
    Ok(frames)
}

impl Animation {
    /// The animation of XYZ frames, one animation frame each (every k-th when there are
    /// more than [`super::MAX_FRAMES`]): the atoms as balls of a radius from the number
    /// density, wrapped into the box on its axes, seen along z.
    pub fn from_xyz(title: &str, frames: &[XyzFrame], options: &AnimationOptions) -> Animation {
        let stride = frames.len().div_ceil(super::MAX_FRAMES).max(1);
        let kept: Vec<&XyzFrame> = frames.iter().step_by(stride).collect();
        let lattice = kept.iter().find_map(|f| f.lattice);
        // the extent: the box, else the atoms' bounds
        let (lo, hi) = match lattice {
            Some(l) => ([0.0; 3], l),
            None => kept.iter().flat_map(|f| f.positions.iter()).fold(
                ([Real::INFINITY; 3], [Real::NEG_INFINITY; 3]),
                |(lo, hi), p| {
                    (
                        std::array::from_fn(|a| lo[a].min(p[a])),
                        std::array::from_fn(|a| hi[a].max(p[a])),
                    )
                },
            ),
        };
        let n = kept.first().map_or(0, |f| f.positions.len()).max(1);
        let span: [Real; 3] = std::array::from_fn(|a| (hi[a] - lo[a]).max(0.0));
        let dims: Vec<Real> = span.iter().copied().filter(|s| *s > 1e-9).collect();
        let volume: Real = dims.iter().product::<Real>().max(1e-300);
        let spacing = if dims.is_empty() {
            1.0
        } else {
            (volume / n as Real).powf(1.0 / dims.len() as Real)
        };
        let radius = 0.45 * spacing;
        let wrap = |p: &[Real; 3]| -> [Real; 3] {
            std::array::from_fn(|a| match lattice {
                Some(l) if l[a] > 0.0 => p[a].rem_euclid(l[a]),
                _ => p[a],
            })
        };
        let depth_range = (lo[2], hi[2].max(lo[2] + 1e-300));
        let margin = radius.max(0.02 * span[0].max(span[1]));
        let view = View {
            x_min: lo[0] - margin,
            x_max: hi[0] + margin,
            y_min: lo[1] - margin,
            y_max: hi[1] + margin,
        };
        let background = if lattice.is_some() {
            vec![Shape {
                geometry: Geometry::Polygon {
                    points: vec![
                        [lo[0], lo[1]],
                        [hi[0], lo[1]],
                        [hi[0], hi[1]],
                        [lo[0], hi[1]],
                    ],
                },
                fill: Some(Colour(245, 245, 250)),
                stroke: Some(Colour(60, 60, 60)),
                line_width: 1.5,
            }]
        } else {
            Vec::new()
        };
        let out_frames: Vec<Frame> = kept
            .iter()
            .map(|f| {
                let mut atoms: Vec<[Real; 3]> = f.positions.iter().map(wrap).collect();
                atoms.sort_by(|a, b| a[2].total_cmp(&b[2]));
                let shapes = atoms
                    .iter()
                    .map(|p| {
                        // nearer (larger z) atoms lighter
                        let s = ((p[2] - depth_range.0) / (depth_range.1 - depth_range.0))
                            .clamp(0.0, 1.0);
                        let shade =
                            |lo: u8, hi: u8| (Real::from(lo) + s * Real::from(hi - lo)) as u8;
                        Shape {
                            geometry: Geometry::Circle {
                                centre: [p[0], p[1]],
                                radius,
                            },
                            fill: Some(Colour(shade(20, 110), shade(70, 170), shade(140, 240))),
                            stroke: Some(Colour(30, 30, 60)),
                            line_width: 0.5,
                        }
                    })
                    .collect();
                Frame {
                    t: f.time,
                    shapes,
                    energy: Vec::new(),
                }
            })
            .collect();
        let duration = kept.last().map_or(0.0, |f| f.time) - kept.first().map_or(0.0, |f| f.time);
        let playback = (out_frames.len().saturating_sub(1)) as Real / options.fps;
        Animation {
            title: title.to_string(),
            fps: options.fps,
            speed: if playback > 0.0 {
                duration / playback
            } else {
                1.0
            },
            view,
            length_unit: "σ".into(),
            background,
            frames: out_frames,
            trails: Vec::new(),
            energy: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_read_and_wrap_into_the_box() {
        let text = "2\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3 Time=0.5 pbc=\"T T T\"\nAr 1 1 1\nAr 5 -1 2\n\
                    2\nLattice=\"4 0 0 0 4 0 0 0 4\" Time=1\nAr 1.5 1 1\nAr 5 -1 2\n";
        let frames = parse_xyz(text).unwrap();
        assert_eq!(frames.len(), 2);
        assert_eq!(frames[0].time, 0.5);
        assert_eq!(frames[0].lattice, Some([4.0; 3]));
        let a = Animation::from_xyz("pair", &frames, &AnimationOptions::default());
        assert_eq!(a.frames.len(), 2);
        let centres: Vec<[Real; 2]> = a.frames[0]
            .shapes
            .iter()
            .filter_map(|s| match s.geometry {
                Geometry::Circle { centre, .. } => Some(centre),
                _ => None,
            })
            .collect();
        assert!(centres.contains(&[1.0, 3.0]), "{centres:?}");
        let e = parse_xyz("2\ncomment\nAr 0 0 0\n").unwrap_err();
        assert!(e.contains("line 4"), "{e}");
        assert!(parse_xyz("x\n").unwrap_err().contains("line 1"));
    }
}
