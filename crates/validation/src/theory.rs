//! The closed-form results the simulation is judged against. Every theory value in the
//! validation report comes from one of these functions, never from a simulation run.

use std::f64::consts::PI;

use physics::DVec2;

/// Constant acceleration: x(t) = x0 + v0 t + a t²/2.
pub(crate) fn constant_acceleration(x0: DVec2, v0: DVec2, a: DVec2, t: f64) -> DVec2 {
    x0 + v0 * t + a * (0.5 * t * t)
}

/// Explicit Euler at a fixed step `h` under constant acceleration, at a multiple t of the
/// step: xₙ₊₁ = xₙ + h vₙ, vₙ₊₁ = vₙ + h a sum to x₀ + v₀t + a·t(t − h)/2 — the exact
/// path less a·t·h/2.
pub(crate) fn explicit_euler_constant_acceleration(
    x0: DVec2,
    v0: DVec2,
    a: DVec2,
    t: f64,
    h: f64,
) -> DVec2 {
    x0 + v0 * t + a * (0.5 * t * (t - h))
}

/// Explicit Euler at a fixed step `h` on the undamped oscillator u'' = −ω²u released at
/// rest from `u0`: z = u + i·u'/ω becomes (1 − iωh)·z each step, so after `n` steps
/// u = u₀ (1 + ω²h²)^(n/2) cos(n·atan ωh). Its energy grows by 1 + (ωh)² per step.
pub(crate) fn explicit_euler_oscillator(u0: f64, omega: f64, h: f64, n: u32) -> f64 {
    let n = f64::from(n);
    u0 * (1.0 + (omega * h).powi(2)).powf(n / 2.0) * (n * (omega * h).atan()).cos()
}

/// Velocities after an impact (the paper's 8–10) with normal `n` from A to B at contact,
/// restitution `e`: `j = −(1 + e) (v_A − v_B)·n / (1/m_A + 1/m_B)`.
pub(crate) fn impact(
    masses: (f64, f64),
    velocities: (DVec2, DVec2),
    n: DVec2,
    e: f64,
) -> (DVec2, DVec2) {
    let ((ma, mb), (va, vb)) = (masses, velocities);
    let j = -(1.0 + e) * (va - vb).dot(n) / (1.0 / ma + 1.0 / mb);
    (va + n * (j / ma), vb - n * (j / mb))
}

/// Acceleration on a frictionless inclined plane at `angle_degrees`: the component of
/// the field along the plane, (g·u) u, magnitude g |sin θ|.
pub(crate) fn inclined_plane(gravity: DVec2, angle_degrees: f64) -> DVec2 {
    let along = DVec2::from_angle(angle_degrees.to_radians());
    along * gravity.dot(along)
}

/// Reflection off a surface with unit normal `n` (the paper's 17–22 with restitution
/// `e`): v∥ kept, v⊥ reversed and scaled by e.
pub(crate) fn reflection(v: DVec2, n: DVec2, e: f64) -> DVec2 {
    v - n * ((1.0 + e) * v.dot(n))
}

/// The damped harmonic oscillator m ü = −k u − b u̇ released at rest from u0:
/// u(t) = u0 e^(−γt) (cos ωt + (γ/ω) sin ωt), γ = b/2m, ω = √(k/m − γ²) (underdamped).
#[derive(Clone, Copy, Debug)]
pub(crate) struct DampedOscillator {
    pub mass: f64,
    pub stiffness: f64,
    pub damping: f64,
    pub start: f64,
}

impl DampedOscillator {
    fn gamma(&self) -> f64 {
        self.damping / (2.0 * self.mass)
    }

    /// Angular frequency of the damped oscillation, rad/s.
    pub fn omega(&self) -> f64 {
        (self.stiffness / self.mass - self.gamma().powi(2)).sqrt()
    }

    /// Displacement from equilibrium at `t`, metres.
    pub fn displacement(&self, t: f64) -> f64 {
        let (gamma, omega) = (self.gamma(), self.omega());
        self.start * (-gamma * t).exp() * ((omega * t).cos() + gamma / omega * (omega * t).sin())
    }

    /// Acceleration at `t`: −(k u + b u̇)/m, with u̇ = −u0 e^(−γt) (ω + γ²/ω) sin ωt.
    pub fn acceleration(&self, t: f64) -> f64 {
        let (gamma, omega) = (self.gamma(), self.omega());
        let velocity =
            -self.start * (-gamma * t).exp() * (omega + gamma * gamma / omega) * (omega * t).sin();
        -(self.stiffness * self.displacement(t) + self.damping * velocity) / self.mass
    }

    /// The k-th maximum of the displacement: at t = 2πk/ω, u0 e^(−γt).
    pub fn peak(&self, k: u32) -> (f64, f64) {
        let t = 2.0 * PI * f64::from(k) / self.omega();
        (t, self.start * (-self.gamma() * t).exp())
    }
}

/// Radial free fall from rest under an inverse-square attraction μ/r² (μ = G(m1 + m2) for
/// gravity, k|q1 q2|(1/m1 + 1/m2) for opposite charges, the relative coordinate):
/// t(r) = √(r0³ / 2μ) (√(u(1 − u)) + arccos √u), u = r/r0.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RadialFall {
    /// Strength of the attraction of the relative coordinate, m³/s².
    pub strength: f64,
    /// Starting separation, metres.
    pub start: f64,
}

impl RadialFall {
    /// Time to fall from the start to separation `r`, seconds.
    pub fn time_to(&self, r: f64) -> f64 {
        let u = (r / self.start).clamp(0.0, 1.0);
        (self.start.powi(3) / (2.0 * self.strength)).sqrt()
            * ((u * (1.0 - u)).sqrt() + u.sqrt().acos())
    }

    /// Separation at time `t` into the fall (the inverse of [`Self::time_to`], which is
    /// monotonic, found by bisection to rounding).
    pub fn separation_at(&self, t: f64) -> f64 {
        let (mut near, mut far) = (0.0, self.start);
        for _ in 0..200 {
            let middle = 0.5 * (near + far);
            if self.time_to(middle) > t {
                near = middle;
            } else {
                far = middle;
            }
            if far - near <= f64::EPSILON * self.start {
                break;
            }
        }
        0.5 * (near + far)
    }

    /// Separation at time `t` for bodies that bounce elastically at separation `contact`:
    /// fall, rise back to the start, fall again, with period 2 t(contact).
    pub fn bouncing_separation(&self, contact: f64, t: f64) -> f64 {
        let fall = self.time_to(contact);
        let phase = t.rem_euclid(2.0 * fall);
        self.separation_at(if phase <= fall {
            phase
        } else {
            2.0 * fall - phase
        })
    }
}

/// K(k), the complete elliptic integral of the first kind, by the arithmetic–geometric
/// mean: K = π / (2 AGM(1, √(1 − k²))), to rounding after a handful of iterations.
pub(crate) fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// The period of a pendulum of length `length` released at rest `amplitude` radians from
/// the downward vertical: 4 √(L/g) K(sin(θ₀/2)).
pub(crate) fn pendulum_period(length: f64, g: f64, amplitude: f64) -> f64 {
    4.0 * (length / g).sqrt() * elliptic_k((amplitude / 2.0).sin())
}

/// Simpson's rule for ∫ f over [a, b] with `n` (even) intervals.
pub(crate) fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: u32) -> f64 {
    let h = (b - a) / f64::from(n);
    let inner: f64 = (1..n)
        .map(|k| f(a + h * f64::from(k)) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + f(b) + inner) * h / 3.0
}

/// The interval [lo, hi] narrowed by bisection to where `f` turns from false to true.
pub(crate) fn bisect(f: impl Fn(f64) -> bool, (mut lo, mut hi): (f64, f64)) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Where a ball launched from the ground at `speed` m/s and `angle` degrees under gravity
/// `g` and quadratic drag (`k` = c/m, 1/m: an acceleration −k |v| v) comes down again:
/// (range, flight time). Integrated here, apart from the simulation: classical
/// Runge–Kutta on (x, y, vx, vy) with a 10 µs step (its truncation error far below the
/// rounding of its 10⁵–10⁶ steps, some 1e-11 of the range),
/// the landing found inside the last step by bisection on the cubic Hermite curve
/// through the step's ends.
pub(crate) fn drag_landing(speed: f64, angle: f64, g: f64, k: f64) -> (f64, f64) {
    let rate = |s: [f64; 4]| {
        let drag = k * (s[2] * s[2] + s[3] * s[3]).sqrt();
        [s[2], s[3], -drag * s[2], -g - drag * s[3]]
    };
    let add = |s: [f64; 4], d: [f64; 4], h: f64| std::array::from_fn(|i| s[i] + h * d[i]);
    let h = 1e-5;
    let (sin, cos) = angle.to_radians().sin_cos();
    let mut s = [0.0, 0.0, speed * cos, speed * sin];
    let mut t = 0.0;
    loop {
        let k1 = rate(s);
        let k2 = rate(add(s, k1, h / 2.0));
        let k3 = rate(add(s, k2, h / 2.0));
        let k4 = rate(add(s, k3, h));
        let next: [f64; 4] =
            std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        if next[1] < 0.0 && t > 0.0 {
            // y and x on the cubic through both ends (positions and velocities).
            let hermite = |p0: f64, v0: f64, p1: f64, v1: f64, u: f64| {
                let (u2, u3) = (u * u, u * u * u);
                (2.0 * u3 - 3.0 * u2 + 1.0) * p0
                    + (u3 - 2.0 * u2 + u) * h * v0
                    + (-2.0 * u3 + 3.0 * u2) * p1
                    + (u3 - u2) * h * v1
            };
            let u = bisect(
                |u| hermite(s[1], s[3], next[1], next[3], u) < 0.0,
                (0.0, 1.0),
            );
            return (hermite(s[0], s[2], next[0], next[2], u), t + u * h);
        }
        s = next;
        t += h;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Without drag the independent integration lands where the sine law says, and its
    /// flight lasts 2 v sin a / g, both to 1e-10 relative (rounding over 4 × 10⁵ steps:
    /// some 7e-12 seen); with drag it lands shorter.
    #[test]
    fn the_drag_landing_without_drag_is_the_sine_law() {
        let (range, flight) = drag_landing(30.0, 35.0, 9.81, 0.0);
        let a = 35_f64.to_radians();
        assert!((range - 900.0 * (2.0 * a).sin() / 9.81).abs() < 1e-10 * range);
        assert!((flight - 60.0 * a.sin() / 9.81).abs() < 1e-10 * flight);
        assert!(drag_landing(30.0, 35.0, 9.81, 0.01).0 < 0.8 * range);
    }

    /// Free fall from r0 = 1 to 0 with μ = 2 takes π/2 √(r0³/2μ) = π/4 (arccos 0 = π/2).
    #[test]
    fn radial_fall_to_the_centre() {
        let fall = RadialFall {
            strength: 2.0,
            start: 1.0,
        };
        assert!((fall.time_to(0.0) - PI / 2.0 * 0.5).abs() < 1e-15, "t(0)");
        assert!(
            (fall.separation_at(fall.time_to(0.4)) - 0.4).abs() < 1e-14,
            "inverse"
        );
    }

    /// Near the start the fall is uniform acceleration: r ≈ r0 − μ t² / 2r0².
    #[test]
    fn radial_fall_starts_like_constant_acceleration() {
        let fall = RadialFall {
            strength: 3.0,
            start: 10.0,
        };
        let t = 1e-3;
        let expected = 10.0 - 3.0 / 100.0 * t * t / 2.0;
        assert!(
            (fall.separation_at(t) - expected).abs() < 1e-12,
            "{}",
            fall.separation_at(t)
        );
    }

    #[test]
    fn undamped_oscillator_is_a_cosine() {
        let spring = DampedOscillator {
            mass: 1.0,
            stiffness: 4.0,
            damping: 0.0,
            start: 5.0,
        };
        assert!(
            (spring.displacement(0.3) - 5.0 * 0.6_f64.cos()).abs() < 1e-15,
            "cos 2t"
        );
        assert!(
            (spring.acceleration(0.3) + 20.0 * 0.6_f64.cos()).abs() < 1e-14,
            "−4 u"
        );
    }
}
