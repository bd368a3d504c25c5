//! The curves a body can be constrained to, as parametrised paths r(q) with r' and r''.

use mechkit_expr::{MapScope, Program};

use super::error::ConstrainedError;
use crate::Real;
use crate::calculus::Params;
use crate::function::Function;
use crate::interval::Jet;
use crate::rigid::Input;

/// Which side of the curve the body is on, relative to the unit normal n (the tangent turned
/// counter-clockwise: up for a graph y(x) traversed in +x, outward for a circle).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// On the side n points to: on top of a graph, outside a circle (a block on a hill, a
    /// particle on a cylinder). The curve can only push along +n.
    Outer,
    /// On the other side: under a graph, inside a circle (a loop-the-loop track). The curve
    /// can only push along −n.
    Inner,
    /// Threaded on the curve (a bead on a wire): it never leaves.
    Bead,
}

impl Side {
    /// The sign of the allowed normal force along n: +1 outer, −1 inner, 0 threaded.
    pub fn sign(self) -> Real {
        match self {
            Side::Outer => 1.0,
            Side::Inner => -1.0,
            Side::Bead => 0.0,
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Circle { radius: Real },
    Graph(Box<Graph>),
}

#[derive(Debug, Clone, PartialEq)]
struct Graph {
    y: Function,
    dy: Function,
    d2y: Function,
    /// `y`, `y'`, `y''` compiled, for enclosures (`None` if one does not compile).
    programs: Option<[Program; 3]>,
}

/// `f(x)` compiled, its parameters folded in.
fn compile(f: &Function) -> Option<Program> {
    let scope = f
        .params()
        .iter()
        .fold(MapScope::new().slot("x", 0), |scope, (name, value)| {
            scope.constant(name, *value)
        });
    Program::compile(&f.sym().to_expr(), &scope).ok()
}

/// A curve in the vertical (x, y) plane, y up: a circle of radius R centred at the origin
/// (coordinate φ, the angle from the top, clockwise: r = (R sin φ, R cos φ)), or a graph y(x)
/// (coordinate x).
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    kind: Kind,
}

/// r(q), r'(q), r''(q).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Geometry {
    pub r: [Real; 2],
    pub d1: [Real; 2],
    pub d2: [Real; 2],
}

impl Geometry {
    /// |r'|.
    pub fn speed_factor(&self) -> Real {
        self.d1[0].hypot(self.d1[1])
    }

    /// The unit normal, the tangent turned counter-clockwise.
    pub fn normal(&self) -> [Real; 2] {
        let s = self.speed_factor();
        [-self.d1[1] / s, self.d1[0] / s]
    }

    /// q̈ under gravity `g`.
    pub fn accel(&self, qd: Real, g: Real) -> Real {
        let dot = self.d1[0] * self.d2[0] + self.d1[1] * self.d2[1];
        let s2 = self.d1[0] * self.d1[0] + self.d1[1] * self.d1[1];
        -(g * self.d1[1] + dot * qd * qd) / s2
    }

    /// The normal force per unit mass along n.
    pub fn normal_force(&self, qd: Real, g: Real) -> Real {
        let n = self.normal();
        (self.d2[0] * n[0] + self.d2[1] * n[1]) * qd * qd + g * n[1]
    }
}

impl Curve {
    /// A circle of radius `radius` (m) centred at the origin.
    pub fn circle(radius: Real) -> Result<Self, ConstrainedError> {
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(ConstrainedError::Value {
                input: Input::Radius,
                what: "the radius",
                value: radius,
                must_be: "positive and finite",
            });
        }
        Ok(Self {
            kind: Kind::Circle { radius },
        })
    }

    /// The graph of the formula `text` of `x` (other names from `params`, SI): y' and y''
    /// symbolically.
    pub fn graph(text: &str, params: &Params) -> Result<Self, ConstrainedError> {
        let y = Function::parse(text, &["x"], params)?;
        let dy = y.diff("x");
        let d2y = dy.diff("x");
        let programs = (|| Some([compile(&y)?, compile(&dy)?, compile(&d2y)?]))();
        Ok(Self {
            kind: Kind::Graph(Box::new(Graph {
                y,
                dy,
                d2y,
                programs,
            })),
        })
    }

    /// The radius, for a circle.
    pub fn radius(&self) -> Option<Real> {
        match self.kind {
            Kind::Circle { radius } => Some(radius),
            Kind::Graph(_) => None,
        }
    }

    /// A description: `circle R = 1 m` or `y = x^2/2`.
    pub fn describe(&self) -> String {
        match &self.kind {
            Kind::Circle { radius } => {
                format!(
                    "circle of radius {} m about the origin",
                    crate::error::short(*radius)
                )
            }
            Kind::Graph(gr) => format!("y = {}", gr.y.sym()),
        }
    }

    /// y'(x) and y''(x) as formulas, for a graph.
    pub fn derivatives(&self) -> Option<(String, String)> {
        match &self.kind {
            Kind::Graph(gr) => Some((gr.dy.sym().to_string(), gr.d2y.sym().to_string())),
            Kind::Circle { .. } => None,
        }
    }

    /// The point at coordinate `q`.
    pub fn point(&self, q: Real) -> [Real; 2] {
        match &self.kind {
            Kind::Circle { radius } => [radius * q.sin(), radius * q.cos()],
            Kind::Graph(gr) => [q, gr.y.at1(q)],
        }
    }

    pub(super) fn geometry(&self, q: Real) -> Geometry {
        match &self.kind {
            Kind::Circle { radius: r } => {
                let (s, c) = q.sin_cos();
                Geometry {
                    r: [r * s, r * c],
                    d1: [r * c, -r * s],
                    d2: [-r * s, -r * c],
                }
            }
            Kind::Graph(gr) => Geometry {
                r: [q, gr.y.at1(q)],
                d1: [1.0, gr.dy.at1(q)],
                d2: [0.0, gr.d2y.at1(q)],
            },
        }
    }

    /// Checks that the curve carries the body at `q` (finite values, not vertical).
    pub(super) fn check_at(&self, q: Real) -> Result<Geometry, ConstrainedError> {
        let g = self.geometry(q);
        let ok = g.r.iter().chain(&g.d1).chain(&g.d2).all(|v| v.is_finite()) && g.d1[1].abs() < 1e8;
        if ok {
            Ok(g)
        } else {
            Err(ConstrainedError::Undefined {
                x: g.r[0],
                y: g.r[1],
                slope: g.d1[1],
            })
        }
    }

    /// The signed distance-like gap of a free point from the curve, positive on the side
    /// `side` (for a graph the vertical gap y − y(x), for a circle |r| − R), NaN where the
    /// graph is undefined.
    pub fn gap(&self, p: [Real; 2], side: Side) -> Real {
        let raw = match &self.kind {
            Kind::Circle { radius } => p[0].hypot(p[1]) - radius,
            Kind::Graph(gr) => p[1] - gr.y.at1(p[0]),
        };
        side.sign() * raw
    }

    /// Encloses the normal force per unit mass along n, `(r''·n) q̇² + g n_y`, over a range of
    /// times from jets of `q` and `q̇`: `g cos φ − R φ̇²` on a circle, `(y'' ẋ² + g)/√(1 + y'²)`
    /// on a graph (`y'`, `y''` by interval arithmetic on their compiled formulas). `None` for a
    /// graph whose formulas do not compile.
    pub(super) fn enclose_normal_force(&self, q: Jet, qd: Jet, g: Real) -> Option<Jet> {
        let c = Jet::constant;
        match &self.kind {
            Kind::Circle { radius } => Some(c(g) * q.cos() - c(*radius) * qd.sqr()),
            Kind::Graph(gr) => {
                let [_, dy, d2y] = gr.programs.as_ref()?;
                let (d1, d2) = (dy.eval_jet(&[q]), d2y.eval_jet(&[q]));
                Some((d2 * qd.sqr() + c(g)) / (c(1.0) + d1.sqr()).sqrt())
            }
        }
    }

    /// Encloses [`Curve::gap`] from jets of the position.
    pub(super) fn enclose_gap(&self, p: [Jet; 2], side: Side) -> Option<Jet> {
        let c = Jet::constant;
        let raw = match &self.kind {
            Kind::Circle { radius } => (p[0].sqr() + p[1].sqr()).sqrt() - c(*radius),
            Kind::Graph(gr) => p[1] - gr.programs.as_ref()?[0].eval_jet(&[p[0]]),
        };
        Some(c(side.sign()) * raw)
    }

    /// The coordinate of the point of the curve nearest a landing point `p` (exact for a
    /// circle; `x` for a graph).
    pub fn coordinate_of(&self, p: [Real; 2]) -> Real {
        match &self.kind {
            Kind::Circle { .. } => p[0].atan2(p[1]),
            Kind::Graph(_) => p[0],
        }
    }

    /// The unit tangent (direction of increasing coordinate) and normal at `q`.
    pub fn frame(&self, q: Real) -> ([Real; 2], [Real; 2]) {
        let g = self.geometry(q);
        let s = g.speed_factor();
        ([g.d1[0] / s, g.d1[1] / s], g.normal())
    }

    /// A graph's `y`, `y'`, `y''` compiled (`None` for a circle, or where one does not
    /// compile).
    pub(super) fn programs(&self) -> Option<&[Program; 3]> {
        match &self.kind {
            Kind::Graph(gr) => gr.programs.as_ref(),
            Kind::Circle { .. } => None,
        }
    }

    /// The length scale used for sampling free flights: R, or 1 m for a graph.
    pub(super) fn scale(&self) -> Real {
        self.radius().unwrap_or(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interval::Interval;

    #[test]
    fn enclosures_hold_the_normal_force_and_the_gap() {
        let params = vec![("a".to_string(), 0.7)];
        let curves = [
            Curve::circle(1.3).unwrap(),
            Curve::graph("a*x^2/2 - sin(x)", &params).unwrap(),
        ];
        let (q, qd) = (Interval::new(0.3, 0.5), Interval::new(-1.2, 1.0));
        let jet = |v: Interval| Jet::new(v, Interval::new(-5.0, 5.0));
        for curve in &curves {
            let n = curve.enclose_normal_force(jet(q), jet(qd), 9.81).unwrap();
            let (x, y) = (Interval::new(0.2, 0.6), Interval::new(0.5, 1.5));
            let gap = curve.enclose_gap([jet(x), jet(y)], Side::Inner).unwrap();
            for i in 0..=10 {
                let f = Real::from(i) / 10.0;
                let (qi, qdi) = (0.3 + 0.2 * f, -1.2 + 2.2 * f);
                let want = curve.geometry(qi).normal_force(qdi, 9.81);
                assert!(
                    n.v.contains(want),
                    "{}: {want} not in {:?}",
                    curve.describe(),
                    n.v
                );
                let p = [0.2 + 0.4 * f, 1.5 - f];
                assert!(gap.v.contains(curve.gap(p, Side::Inner)));
            }
        }
    }
}
