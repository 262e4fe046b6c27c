//! The integration methods over a small system of bodies whose accelerations depend on
//! where they are and how they move (jointed bodies: a pendulum's pull changes as it
//! swings): each method's own step, as the particles take it, on positions (x, y, angle
//! in radians) and velocities (vx, vy, spin).

use glam::DVec3;

use crate::Integrator;
use crate::integrators::{dopri5, pefrl};

/// The accelerations at positions `q` and velocities `u`.
pub(crate) type Slope<'a> = dyn Fn(&[DVec3], &[DVec3]) -> Vec<DVec3> + 'a;

/// `x + k·y`, element by element.
fn plus(x: &[DVec3], y: &[DVec3], k: f64) -> Vec<DVec3> {
    x.iter().zip(y).map(|(&x, &y)| x + y * k).collect()
}

fn add(x: &mut [DVec3], y: &[DVec3], k: f64) {
    for (x, &y) in x.iter_mut().zip(y) {
        *x += y * k;
    }
}

/// Advances `q` and `u` by `h` seconds with `method` (dopri5: one fifth-order step, no
/// error control; the particles' controller chose `h`).
pub(crate) fn step(method: Integrator, q: &mut [DVec3], u: &mut [DVec3], h: f64, slope: &Slope) {
    match method {
        Integrator::Euler => {
            let a = slope(q, u);
            add(q, u, h);
            add(u, &a, h);
        }
        Integrator::SemiImplicitEuler => {
            let a = slope(q, u);
            add(u, &a, h);
            add(q, u, h);
        }
        Integrator::Verlet => {
            let start = slope(q, u);
            let predicted = plus(u, &start, h);
            add(u, &start, 0.5 * h);
            add(q, u, h);
            let end = slope(q, &predicted);
            add(u, &end, 0.5 * h);
        }
        Integrator::Rk4 => runge_kutta(&RK4, q, u, h, slope),
        Integrator::Dopri5 => runge_kutta(&DOPRI5, q, u, h, slope),
        Integrator::Pefrl => {
            let drifts = [
                pefrl::XI,
                pefrl::CHI,
                1.0 - 2.0 * (pefrl::CHI + pefrl::XI),
                pefrl::CHI,
                pefrl::XI,
            ];
            let edge = 0.5 * (1.0 - 2.0 * pefrl::LAMBDA);
            let kicks = [edge, pefrl::LAMBDA, pefrl::LAMBDA, edge];
            for (k, drift) in drifts.iter().enumerate() {
                add(q, u, drift * h);
                if let Some(kick) = kicks.get(k) {
                    kick_in_stages(q, u, kick * h, slope);
                }
            }
        }
    }
}

/// v' = a(q, v) over `duration` at fixed positions, by one classical Runge–Kutta step,
/// as the particles' PEFRL kicks under velocity-dependent forces.
fn kick_in_stages(q: &[DVec3], u: &mut [DVec3], duration: f64, slope: &Slope) {
    let k1 = slope(q, u);
    let k2 = slope(q, &plus(u, &k1, 0.5 * duration));
    let k3 = slope(q, &plus(u, &k2, 0.5 * duration));
    let k4 = slope(q, &plus(u, &k3, duration));
    for i in 0..u.len() {
        u[i] += (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) * (duration / 6.0);
    }
}

/// An explicit Runge–Kutta method: each stage's weights on the earlier stages, and the
/// solution's weights.
struct Tableau<const S: usize> {
    a: [[f64; 6]; S],
    b: [f64; S],
}

const RK4: Tableau<4> = Tableau {
    a: [
        [0.0; 6],
        [0.5, 0.0, 0.0, 0.0, 0.0, 0.0],
        [0.0, 0.5, 0.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
    ],
    b: [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
};

/// Dormand–Prince's first six stages; its fifth-order solution is the seventh stage's
/// row.
const DOPRI5: Tableau<6> = Tableau {
    a: [
        dopri5::A[0],
        dopri5::A[1],
        dopri5::A[2],
        dopri5::A[3],
        dopri5::A[4],
        dopri5::A[5],
    ],
    b: [
        dopri5::A[6][0],
        dopri5::A[6][1],
        dopri5::A[6][2],
        dopri5::A[6][3],
        dopri5::A[6][4],
        dopri5::A[6][5],
    ],
};

fn runge_kutta<const S: usize>(
    tableau: &Tableau<S>,
    q: &mut [DVec3],
    u: &mut [DVec3],
    h: f64,
    slope: &Slope,
) {
    let mut kq: Vec<Vec<DVec3>> = Vec::with_capacity(S);
    let mut ku: Vec<Vec<DVec3>> = Vec::with_capacity(S);
    for s in 0..S {
        let mut stage_q = q.to_vec();
        let mut stage_u = u.to_vec();
        for (r, &weight) in tableau.a[s][..s].iter().enumerate() {
            if weight != 0.0 {
                add(&mut stage_q, &kq[r], weight * h);
                add(&mut stage_u, &ku[r], weight * h);
            }
        }
        ku.push(slope(&stage_q, &stage_u));
        kq.push(stage_u);
    }
    for (s, &weight) in tableau.b.iter().enumerate() {
        if weight != 0.0 {
            add(q, &kq[s], weight * h);
            add(u, &ku[s], weight * h);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each method on the pendulum θ'' = −sin θ (written here as x'' = −sin x in the first
    /// component) keeps its order: halving the step divides the error after 1 s by 2ᵖ
    /// within 20 % (the reference is rk4 at 1/64 of the step).
    #[test]
    fn every_method_keeps_its_order() {
        let slope = |q: &[DVec3], _u: &[DVec3]| vec![DVec3::new(-q[0].x.sin(), 0.0, 0.0)];
        let run = |method, n: u32| {
            let (mut q, mut u) = (vec![DVec3::new(1.0, 0.0, 0.0)], vec![DVec3::ZERO]);
            for _ in 0..n {
                step(method, &mut q, &mut u, 1.0 / f64::from(n), &slope);
            }
            q[0].x
        };
        let exact = run(Integrator::Dopri5, 4096);
        for (method, order) in [
            (Integrator::Euler, 1),
            (Integrator::SemiImplicitEuler, 1),
            (Integrator::Verlet, 2),
            (Integrator::Rk4, 4),
            (Integrator::Pefrl, 4),
            (Integrator::Dopri5, 5),
        ] {
            let coarse = (run(method, 32) - exact).abs();
            let fine = (run(method, 64) - exact).abs();
            let ratio = (coarse / fine).log2();
            assert!(
                (ratio - f64::from(order)).abs() < 0.2 * f64::from(order),
                "{method}: error ratio 2^{ratio:.2}, order {order}"
            );
        }
    }
}
