//! Relative motion: the Galilean transformation between frames in uniform relative motion, and
//! steering through a moving medium (a plane in a crosswind, a boat crossing a river).
//!
//! A frame `A` moving with velocity `u` relative to a frame `B` (its origin at `r₀` when
//! `t = 0`) sees a body at `r_A`, `v_A` where `B` sees it at
//! `r_B = r_A + r₀ + u t`, `v_B = v_A + u`; accelerations agree.
//!
//! Steering: a craft moves at `speed` relative to a medium that moves with `current` over
//! the ground. To travel over the ground along the direction `track`, it must cancel the part
//! of the current across the track with part of its own velocity, and the rest of its speed,
//! plus the current along the track, is its ground speed. With the current straight across
//! the track, the ground speed is `√(s² − c²)` and the heading makes the angle
//! `acos(c/s)` with the upstream direction.
//! ```
//! use mechkit::relative::steer;
//! // a plane at 300 km/h that must fly north (+y) in a 60 km/h wind blowing east (+x)
//! let s = steer(300.0, [60.0, 0.0], [0.0, 1.0]).unwrap();
//! assert!((s.ground_speed - (300.0f64.powi(2) - 60.0f64.powi(2)).sqrt()).abs() < 1e-9);
//! assert!((s.angle_to_upstream.to_degrees() - 78.463).abs() < 1e-3);
//! ```

use thiserror::Error;

use crate::Real;

/// Why a steering problem has no solution.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RelativeError {
    /// The speed is not positive and finite.
    #[error("the speed relative to the medium must be positive and finite, not {}", crate::error::short(*.0))]
    Speed(Real),
    /// The track direction has no length (or is not finite).
    #[error("the direction of travel has no length: give a direction such as [0, 1] (north)")]
    Track,
    /// The current across the track is faster than the craft.
    #[error(
        "the current across the track ({} m/s) is faster than the craft moves through the medium ({} m/s): no heading keeps it on the track",
        crate::error::short(across.abs()),
        crate::error::short(*speed)
    )]
    TooMuchCross {
        /// The component of the current across the track.
        across: Real,
        /// The craft's speed relative to the medium.
        speed: Real,
    },
    /// A velocity and a frame velocity of different dimensions.
    #[error("{}", components_message(*velocity, *frame))]
    Components {
        /// The velocity's number of components.
        velocity: usize,
        /// The frame velocity's.
        frame: usize,
    },
    /// The craft can hold the track's line but is carried backwards along it.
    #[error(
        "on the track's line the ground speed would be {} m/s: the current against the track is stronger than the craft can make up",
        crate::error::short(*ground_speed)
    )]
    NoProgress {
        /// The (non-positive) ground speed along the track.
        ground_speed: Real,
    },
}

/// `1 component`, `2 components`.
pub fn components(n: usize) -> String {
    if n == 1 {
        "1 component".to_string()
    } else {
        format!("{n} components")
    }
}

fn components_message(velocity: usize, frame: usize) -> String {
    format!(
        "the velocity has {} and the frame's velocity {}: give both in the same dimensions",
        components(velocity),
        components(frame)
    )
}

/// The velocity in frame `B` of a body moving with `v_in_a` in frame `A`, when `A` moves with
/// `frame_velocity` relative to `B` (Galilean: `v_B = v_A + u`).
pub fn velocity_in_b<const N: usize>(v_in_a: [Real; N], frame_velocity: [Real; N]) -> [Real; N] {
    std::array::from_fn(|i| v_in_a[i] + frame_velocity[i])
}

/// The velocity in frame `A` of a body moving with `v_in_b` in frame `B` (`v_A = v_B − u`).
pub fn velocity_in_a<const N: usize>(v_in_b: [Real; N], frame_velocity: [Real; N]) -> [Real; N] {
    std::array::from_fn(|i| v_in_b[i] - frame_velocity[i])
}

/// The position in frame `B` at time `t` of a point at `r_in_a` in frame `A`, whose origin
/// is at `origin` in `B` at `t = 0` and moves with `frame_velocity`.
pub fn position_in_b<const N: usize>(
    r_in_a: [Real; N],
    origin: [Real; N],
    frame_velocity: [Real; N],
    t: Real,
) -> [Real; N] {
    std::array::from_fn(|i| r_in_a[i] + origin[i] + frame_velocity[i] * t)
}

/// The solution of a steering problem, in the plane of the motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steering {
    /// The unit vector the craft points along (its velocity relative to the medium, divided
    /// by its speed).
    pub heading: [Real; 2],
    /// The velocity over the ground (along the track).
    pub ground_velocity: [Real; 2],
    /// The speed over the ground.
    pub ground_speed: Real,
    /// The angle between the heading and the track (the correction into the current), in
    /// radians, positive counter-clockwise from the track to the heading.
    pub correction: Real,
    /// The angle between the heading and the direction the current comes from (`−current`),
    /// in radians, in `[0, π]`; `NaN` without a current. This is the textbook's angle "to the
    /// bank, upstream" when the current is across the track.
    pub angle_to_upstream: Real,
    /// The current's component along the track (positive: a tailwind).
    pub along: Real,
    /// The current's component across the track (positive: to the left of the track).
    pub across: Real,
}

/// Steers a craft of `speed` relative to a medium moving with `current` so that it travels over
/// the ground along `track` (any non-zero vector). Fails when the current across the track is
/// faster than the craft, or when the craft would not make progress along the track.
pub fn steer(speed: Real, current: [Real; 2], track: [Real; 2]) -> Result<Steering, RelativeError> {
    if !(speed > 0.0 && speed.is_finite()) {
        return Err(RelativeError::Speed(speed));
    }
    let norm = track[0].hypot(track[1]);
    if !(norm > 0.0 && norm.is_finite()) {
        return Err(RelativeError::Track);
    }
    let t = [track[0] / norm, track[1] / norm];
    let left = [-t[1], t[0]];
    let along = current[0] * t[0] + current[1] * t[1];
    let across = current[0] * left[0] + current[1] * left[1];
    if across.abs() > speed {
        return Err(RelativeError::TooMuchCross { across, speed });
    }
    // the craft's own velocity cancels the current across the track
    let own_across = -across;
    // √(s² − a²) as s √((1 − r)(1 + r)), r = a/s: the squares overflow from about 1e154
    // and underflow below 1e-154
    let r = across / speed;
    let own_along = speed * ((1.0 - r) * (1.0 + r)).max(0.0).sqrt();
    let ground_speed = own_along + along;
    if ground_speed <= 0.0 {
        return Err(RelativeError::NoProgress { ground_speed });
    }
    let heading = [
        (own_along * t[0] + own_across * left[0]) / speed,
        (own_along * t[1] + own_across * left[1]) / speed,
    ];
    let current_speed = current[0].hypot(current[1]);
    let angle_to_upstream = if current_speed > 0.0 {
        let cos = -(heading[0] * current[0] + heading[1] * current[1]) / current_speed;
        cos.clamp(-1.0, 1.0).acos()
    } else {
        Real::NAN
    };
    Ok(Steering {
        heading,
        ground_velocity: [ground_speed * t[0], ground_speed * t[1]],
        ground_speed,
        correction: own_across.atan2(own_along),
        angle_to_upstream,
        along,
        across,
    })
}

/// The unit vector at `angle` (rad) counter-clockwise from +x (east); exact for the compass
/// directions (`cos 90° = 0`, not 6e-17).
pub fn direction(angle: Real) -> [Real; 2] {
    let (s, c) = angle.sin_cos();
    let clean = |x: Real| if x.abs() < 1e-15 { 0.0 } else { x };
    [clean(c), clean(s)]
}

/// The bearing of `v` in degrees counter-clockwise from +x (east), in `[0, 360)`.
pub fn bearing_deg(v: [Real; 2]) -> Real {
    let a = v[1].atan2(v[0]).to_degrees();
    if a < 0.0 { a + 360.0 } else { a }
}

/// The unit speeds are given in: its name and its size in m/s.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedUnit {
    /// The name (`m/s`, `km/h`, `knot`).
    pub name: String,
    /// Its size in m/s.
    pub size: Real,
}

impl Default for SpeedUnit {
    /// m/s.
    fn default() -> Self {
        Self {
            name: "m/s".to_string(),
            size: 1.0,
        }
    }
}

/// A steering problem's answer as `mechkit relative` reports it, speeds in `unit`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SteeringReport {
    /// The unit of the speeds.
    pub unit: String,
    /// The craft's speed through the medium.
    pub speed: Real,
    /// The medium's velocity over the ground.
    pub current: [Real; 2],
    /// The unit vector of the heading.
    pub heading: [Real; 2],
    /// The heading's bearing (degrees counter-clockwise from east).
    pub heading_deg: Real,
    /// The correction into the current, from the track to the heading (degrees,
    /// counter-clockwise positive).
    pub correction_deg: Real,
    /// The angle between the heading and upstream (degrees), without a current `None`.
    pub angle_to_upstream_deg: Option<Real>,
    /// The velocity over the ground.
    pub ground_velocity: [Real; 2],
    /// The speed over the ground.
    pub ground_speed: Real,
    /// The current along the track.
    pub current_along_track: Real,
    /// The current across it (positive: to the left).
    pub current_across_track: Real,
}

/// Steers a craft of `speed` (m/s) through a medium moving at `current_speed` (m/s) towards
/// the bearing `current_bearing` (rad from east) along the track at the bearing
/// `track_bearing` ([`steer`]), the speeds reported in `unit`.
///
/// ```
/// use mechkit::relative::{SpeedUnit, steering_report};
/// let r = steering_report(2.0, 1.0, 0.0, 90f64.to_radians(), &SpeedUnit::default()).unwrap();
/// assert!((r.heading_deg - 120.0).abs() < 1e-9);
/// assert!((r.ground_speed - 3f64.sqrt()).abs() < 1e-12);
/// ```
pub fn steering_report(
    speed: Real,
    current_speed: Real,
    current_bearing: Real,
    track_bearing: Real,
    unit: &SpeedUnit,
) -> Result<SteeringReport, RelativeError> {
    let current = direction(current_bearing).map(|x| x * current_speed);
    let st = steer(speed, current, direction(track_bearing))?;
    let upstream = st.angle_to_upstream.to_degrees();
    let k = unit.size;
    Ok(SteeringReport {
        unit: unit.name.clone(),
        speed: speed / k,
        current: current.map(|x| x / k),
        heading: st.heading,
        heading_deg: bearing_deg(st.heading),
        correction_deg: st.correction.to_degrees(),
        angle_to_upstream_deg: upstream.is_finite().then_some(upstream),
        ground_velocity: st.ground_velocity.map(|x| x / k),
        ground_speed: st.ground_speed / k,
        current_along_track: st.along / k,
        current_across_track: st.across / k,
    })
}

/// The length of `v`, scaled by its largest component before squaring (no overflow or
/// underflow of the squares: `|(3e200, 4e200)| = 5e200`).
fn norm(v: &[Real]) -> Real {
    let big = v.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
    if big == 0.0 || !big.is_finite() {
        return big;
    }
    big * v.iter().map(|x| (x / big) * (x / big)).sum::<Real>().sqrt()
}

/// Which frame a transformed velocity is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Over the ground: the velocity was measured in a frame moving with `u`, `v + u`.
    Ground,
    /// As an observer moving with `u` sees a velocity measured on the ground, `v − u`.
    Observer,
}

/// A velocity in another frame, as `mechkit relative` reports it, in `unit`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct VelocityReport {
    /// The unit of the speeds.
    pub unit: String,
    /// The velocity (1 to 3 components).
    pub velocity: Vec<Real>,
    /// Its size.
    pub speed: Real,
    /// `ground` or `observer`.
    pub frame: &'static str,
    /// Its bearing in the plane (degrees from +x), with two or more components.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub angle_deg: Option<Real>,
}

/// The velocity `v` (m/s, 1 to 3 components) in `frame`, the frame's velocity `u` (m/s),
/// reported in `unit`.
///
/// ```
/// use mechkit::relative::{Frame, SpeedUnit, transform};
/// // rain falling at 8 m/s seen from a car at 15 m/s
/// let r = transform(&[0.0, -8.0], &[15.0, 0.0], Frame::Observer, &SpeedUnit::default()).unwrap();
/// assert_eq!(r.velocity, [-15.0, -8.0]);
/// assert_eq!(r.speed, 17.0);
/// ```
pub fn transform(
    v: &[Real],
    u: &[Real],
    frame: Frame,
    unit: &SpeedUnit,
) -> Result<VelocityReport, RelativeError> {
    if v.len() != u.len() || !(1..=3).contains(&v.len()) {
        return Err(RelativeError::Components {
            velocity: v.len(),
            frame: u.len(),
        });
    }
    let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
    a[..v.len()].copy_from_slice(v);
    b[..u.len()].copy_from_slice(u);
    let r = match frame {
        Frame::Ground => velocity_in_b(a, b),
        Frame::Observer => velocity_in_a(a, b),
    };
    let r = &r[..v.len()];
    Ok(VelocityReport {
        unit: unit.name.clone(),
        velocity: r.iter().map(|x| x / unit.size).collect(),
        speed: norm(r) / unit.size,
        frame: match frame {
            Frame::Ground => "ground",
            Frame::Observer => "observer",
        },
        angle_deg: (r.len() >= 2).then(|| bearing_deg([r[0], r[1]])),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ground_velocity_is_the_sum_of_the_own_velocity_and_the_current() {
        for (speed, current, track) in [
            (300.0, [60.0, 0.0], [0.0, 1.0]),
            (5.0, [-1.5, 2.0], [1.0, 1.0]),
            (2.0, [0.0, -1.0], [3.0, -4.0]),
        ] {
            let s = steer(speed, current, track).expect("solvable");
            let own = [s.heading[0] * speed, s.heading[1] * speed];
            let sum = velocity_in_b(own, current);
            for (a, b) in sum.iter().zip(&s.ground_velocity) {
                assert!((a - b).abs() < 1e-12 * speed);
            }
            // along the track, and forwards
            let n = track[0].hypot(track[1]);
            let cross = s.ground_velocity[0] * track[1] / n - s.ground_velocity[1] * track[0] / n;
            assert!(cross.abs() < 1e-12 * speed);
            assert!(s.ground_speed > 0.0);
            assert!((s.heading[0].hypot(s.heading[1]) - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn a_river_crossing_heads_upstream_at_acos_of_the_speed_ratio() {
        // a boat at 2 m/s crossing (+y) a river flowing at 1 m/s (+x)
        let s = steer(2.0, [1.0, 0.0], [0.0, 1.0]).expect("solvable");
        assert!((s.ground_speed - 3.0f64.sqrt()).abs() < 1e-15);
        assert!((s.angle_to_upstream - 0.5f64.acos()).abs() < 1e-15);
        assert!((s.correction - 30f64.to_radians()).abs() < 1e-15);
        assert_eq!(s.across, -1.0);
    }

    #[test]
    fn impossible_crossings_say_why() {
        assert!(matches!(
            steer(1.0, [2.0, 0.0], [0.0, 1.0]),
            Err(RelativeError::TooMuchCross { .. })
        ));
        assert!(matches!(
            steer(1.0, [0.0, -2.0], [0.0, 1.0]),
            Err(RelativeError::NoProgress { .. })
        ));
        assert_eq!(
            steer(1.0, [0.0, 0.0], [0.0, 0.0]),
            Err(RelativeError::Track)
        );
        assert_eq!(
            steer(0.0, [0.0, 0.0], [0.0, 1.0]),
            Err(RelativeError::Speed(0.0))
        );
    }

    #[test]
    fn reports_convert_units_and_count_components() {
        let kmh = SpeedUnit {
            name: "km/h".to_string(),
            size: 1.0 / 3.6,
        };
        let r = steering_report(300.0 / 3.6, 60.0 / 3.6, 0.0, 90f64.to_radians(), &kmh).unwrap();
        assert!((r.ground_speed - (300.0f64.powi(2) - 60.0f64.powi(2)).sqrt()).abs() < 1e-9);
        assert!((r.current_across_track + 60.0).abs() < 1e-12);
        assert_eq!(direction(90f64.to_radians()), [0.0, 1.0]);
        assert_eq!(bearing_deg([0.0, -1.0]), 270.0);
        let e = transform(&[1.0], &[1.0, 2.0], Frame::Ground, &kmh).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the velocity has 1 component and the frame's velocity 2 components: give both in the same dimensions"
        );
        let back = transform(
            &[-15.0, -8.0],
            &[15.0, 0.0],
            Frame::Ground,
            &SpeedUnit::default(),
        )
        .unwrap();
        assert_eq!(back.velocity, [0.0, -8.0]);
        assert_eq!(back.angle_deg, Some(270.0));
    }

    #[test]
    fn positions_and_velocities_transform_back_and_forth() {
        let u = [3.0, -1.0, 0.5];
        let v = [1.0, 2.0, 3.0];
        assert_eq!(velocity_in_a(velocity_in_b(v, u), u), v);
        assert_eq!(
            position_in_b([1.0, 0.0, 0.0], [0.0, 2.0, 0.0], u, 2.0),
            [7.0, 0.0, 1.0]
        );
    }

    #[test]
    fn steering_and_speeds_hold_at_the_ends_of_the_double_range() {
        // a current at 45° as fast as the craft, the track east: heading 315°, ground speed
        // √2 times the speed, at any scale (the squares overflow from 1e154, underflow at 1e-200)
        for scale in [1.0, 1e155, 1e300, 1e-200, 1e-300] {
            let r = steering_report(scale, scale, 45f64.to_radians(), 0.0, &SpeedUnit::default())
                .unwrap();
            assert!((r.heading_deg - 315.0).abs() < 1e-9, "{scale}: {r:?}");
            assert!(
                (r.ground_speed / scale - 2f64.sqrt()).abs() < 1e-12,
                "{scale}: {r:?}"
            );
        }
        for scale in [1e200, 1e-200] {
            let v = transform(
                &[3.0 * scale, 0.0],
                &[0.0, 4.0 * scale],
                Frame::Ground,
                &SpeedUnit::default(),
            )
            .unwrap();
            assert!((v.speed / scale - 5.0).abs() < 1e-12, "{scale}: {v:?}");
        }
    }
}
