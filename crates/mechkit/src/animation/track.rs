//! Where the bodies are at a frame's time: their columns interpolated between the run's rows
//! (cubic Hermite with the velocities, angles with ω, quaternions normalised), their poses, and
//! the two axes the picture keeps.

use super::build::{AnimationError, Columns};
use super::scene::{Body, Scene};
use crate::Real;

/// Where each body is over the run: its position columns and, when it turns, its angle or
/// quaternion columns, with the velocities that go with them.
pub(super) struct Track<'a> {
    pub(super) position: Vec<(&'a [Real], Option<&'a [Real]>)>,
    turn: Turn<'a>,
}

pub(super) enum Turn<'a> {
    None,
    Angle(&'a [Real], Option<&'a [Real]>),
    /// About a fixed axis (a hinged body).
    Axis([Real; 3], &'a [Real], Option<&'a [Real]>),
    Quaternion([&'a [Real]; 4]),
}

/// Interpolation between rows `i` and `i + 1` at fraction `s`: cubic Hermite with the
/// derivative `dv` when given, else linear; `h` is the rows' time step.
pub(super) fn hermite(x: &[Real], dv: Option<&[Real]>, i: usize, s: Real, h: Real) -> Real {
    let j = (i + 1).min(x.len() - 1);
    let (x0, x1) = (x[i], x[j]);
    match dv {
        Some(v) if j > i && h > 0.0 => {
            let (s2, s3) = (s * s, s * s * s);
            (2.0 * s3 - 3.0 * s2 + 1.0) * x0
                + (s3 - 2.0 * s2 + s) * h * v[i]
                + (-2.0 * s3 + 3.0 * s2) * x1
                + (s3 - s2) * h * v[j]
        }
        _ => x0 + s * (x1 - x0),
    }
}

/// The row interval holding time `t` and the fraction of the way through it.
pub(super) fn locate(times: &[Real], t: Real) -> (usize, Real, Real) {
    let n = times.len();
    if n < 2 || t <= times[0] {
        return (0, 0.0, 0.0);
    }
    // the last row at or before t
    let i = times
        .partition_point(|&x| x <= t)
        .saturating_sub(1)
        .min(n - 2);
    let h = times[i + 1] - times[i];
    if h > 0.0 {
        (i, ((t - times[i]) / h).clamp(0.0, 1.0), h)
    } else {
        (i + 1, 0.0, 0.0)
    }
}

/// Turns `r` (body frame) by the state of a body at interpolation point `(i, s, h)`.
pub(super) struct Pose {
    pub(super) centre: [Real; 3],
    /// Rows of the rotation matrix body → world.
    pub(super) rotation: [[Real; 3]; 3],
}

impl Pose {
    pub(super) fn apply(&self, r: [Real; 3]) -> [Real; 3] {
        let m = &self.rotation;
        std::array::from_fn(|a| self.centre[a] + m[a][0] * r[0] + m[a][1] * r[1] + m[a][2] * r[2])
    }
}

pub(super) fn rotation_z(theta: Real) -> [[Real; 3]; 3] {
    let (s, c) = theta.sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

/// The turn by `theta` about `axis` (Rodrigues).
pub(super) fn rotation_axis(axis: [Real; 3], theta: Real) -> [[Real; 3]; 3] {
    let half = 0.5 * theta;
    let n = axis.iter().map(|x| x * x).sum::<Real>().sqrt();
    let (s, c) = half.sin_cos();
    if n > 0.0 {
        rotation_q([c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n])
    } else {
        rotation_z(0.0)
    }
}

pub(super) fn rotation_q(q: [Real; 4]) -> [[Real; 3]; 3] {
    let n = q.iter().map(|x| x * x).sum::<Real>().sqrt();
    let [w, x, y, z] = if n > 0.0 {
        q.map(|c| c / n)
    } else {
        [1.0, 0.0, 0.0, 0.0]
    };
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

pub(super) const AXES: [&str; 3] = ["x", "y", "z"];

impl<'a> Track<'a> {
    pub(super) fn new(
        body: &Body,
        dim: usize,
        table: &'a (impl Columns + ?Sized),
    ) -> Result<Self, AnimationError> {
        if let Some(axis) = body.hinge {
            let name = format!("{}.theta", body.name);
            let theta = table
                .column(&name)
                .ok_or(AnimationError::MissingColumn(name))?;
            let omega = table.column(&format!("{}.omega", body.name));
            return Ok(Self {
                position: Vec::new(),
                turn: Turn::Axis(axis, theta, omega),
            });
        }
        let mut position = Vec::with_capacity(dim);
        for axis in &AXES[..dim] {
            let name = format!("{}.{axis}", body.name);
            let x = table
                .column(&name)
                .ok_or(AnimationError::MissingColumn(name))?;
            position.push((x, table.column(&format!("{}.v{axis}", body.name))));
        }
        let turn = if let Some(theta) = table.column(&format!("{}.theta", body.name)) {
            Turn::Angle(theta, table.column(&format!("{}.omega", body.name)))
        } else if let (Some(a), Some(b), Some(c), Some(d)) = (
            table.column(&format!("{}.q0", body.name)),
            table.column(&format!("{}.q1", body.name)),
            table.column(&format!("{}.q2", body.name)),
            table.column(&format!("{}.q3", body.name)),
        ) {
            Turn::Quaternion([a, b, c, d])
        } else {
            Turn::None
        };
        Ok(Self { position, turn })
    }

    pub(super) fn pose(&self, (i, s, h): (usize, Real, Real)) -> Pose {
        let mut centre = [0.0; 3];
        for (a, (x, v)) in self.position.iter().enumerate() {
            centre[a] = hermite(x, *v, i, s, h);
        }
        let rotation = match &self.turn {
            Turn::None => rotation_z(0.0),
            Turn::Angle(theta, omega) => rotation_z(hermite(theta, *omega, i, s, h)),
            Turn::Axis(axis, theta, omega) => rotation_axis(*axis, hermite(theta, *omega, i, s, h)),
            Turn::Quaternion(q) => {
                rotation_q(std::array::from_fn(|k| hermite(q[k], None, i, s, h)))
            }
        };
        Pose { centre, rotation }
    }
}

/// How world points (3 components) become picture points (2): the two axes kept.
#[derive(Clone, Copy)]
pub(super) struct Projection {
    axes: [usize; 2],
    /// A 1-D run drawn upright: its x is the picture's vertical.
    upright: bool,
}

impl Projection {
    pub(super) fn apply(self, p: [Real; 3]) -> [Real; 2] {
        if self.upright {
            [0.0, p[0]]
        } else {
            [p[self.axes[0]], p[self.axes[1]]]
        }
    }
}

/// The axes a 3-D run is seen along: the two that move most (a top view of a conical
/// pendulum, a side view of a projectile).
pub(super) fn projection(scene: &Scene, tracks: &[Track<'_>]) -> Projection {
    // bodies turning about fixed axes are seen along the first one's axis
    if let Some(axis) = scene.bodies.iter().find_map(|b| b.hinge) {
        let along = (0..3)
            .max_by(|&a, &b| axis[a].abs().total_cmp(&axis[b].abs()))
            .unwrap_or(2);
        let kept: Vec<usize> = (0..3).filter(|&a| a != along).collect();
        return Projection {
            axes: [kept[0], kept[1]],
            upright: false,
        };
    }
    if scene.dim < 3 {
        return Projection {
            axes: [0, 1],
            upright: scene.dim == 1 && scene.upright,
        };
    }
    let extent = |a: usize| {
        tracks
            .iter()
            .filter_map(|t| t.position.get(a))
            .flat_map(|p| p.0.iter().copied())
            .filter(|x| x.is_finite())
            .fold((Real::INFINITY, Real::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            })
    };
    let spans: Vec<Real> = (0..3)
        .map(|a| {
            let (lo, hi) = extent(a);
            if hi >= lo { hi - lo } else { 0.0 }
        })
        .collect();
    // drop the axis of least motion; ties keep x and y
    let drop = (0..3)
        .rev()
        .min_by(|&a, &b| spans[a].total_cmp(&spans[b]))
        .unwrap_or(2);
    let kept: Vec<usize> = (0..3).filter(|&a| a != drop).collect();
    Projection {
        axes: [kept[0], kept[1]],
        upright: false,
    }
}
