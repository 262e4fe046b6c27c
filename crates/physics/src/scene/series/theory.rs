//! [`Theory`]: the law a series is expected to follow, an expression of the varied value
//! and the scene's constants.

use super::Setting;
use crate::scene::{Scene, say};

/// The law a series is expected to follow: an expression of the varied value (`x`, also
/// `a`; an angle in radians, the file's degrees converted) and of the scene's constants:
/// `g`, the field's strength (m/s²); of the varied particle, `m` (kg), `r` (m), `v0`
/// (its speed at the start, m/s), `h` (its height at the start, m), `b` and `c` (its
/// air resistance; c from the drag coefficient when it has one) and `L` (the length of the first rod or string holding it); of a
/// varied rod or string `L` (m), of a varied spring `k` (N/m) and `L` (its natural
/// length). `v0^2*sin(2*a)/g` is the range of a projectile launched
/// from the ground at the angle varied. Arithmetic as the app's fields: + − × ÷ ^, sqrt,
/// sin, cos, tan, asin, acos, atan, exp, ln, log10, abs, `pi` (or `PI`), and `K`, the complete
/// elliptic integral of the first kind K(k) (a pendulum's period is
/// `4*sqrt(L/g)*K(sin(θ₀/2))`).
#[derive(Clone, Debug)]
pub struct Theory {
    expression: exmex::FlatEx<f64, TheoryOps>,
    /// The values of the expression's variables but the varied one, in its order; the
    /// varied one's place.
    constants: Vec<f64>,
    varied: Vec<usize>,
    /// Whether the varied value is an angle (degrees, turned into radians).
    angle: bool,
}

impl Theory {
    /// Reads `text` for the series varying `vary` on `scene`.
    ///
    /// # Errors
    /// The text is no expression, or names something that is not one of the variables
    /// above (in words, with the names there are).
    pub fn parse(text: &str, scene: &Scene, vary: &str) -> Result<Self, String> {
        use exmex::Express as _;
        let setting = Setting::parse(vary, scene)?;
        if let Some(reason) = crate::units::too_big(text.trim()) {
            return Err(reason);
        }
        let expression = exmex::FlatEx::<f64, TheoryOps>::parse(text.trim())
            .map_err(|_| say("theory-unreadable", &[("text", text.trim())]))?;
        let named = setting.constants(scene);
        let mut constants = Vec::new();
        let mut varied = Vec::new();
        for (k, name) in expression.var_names().iter().enumerate() {
            if name == "x" || name == "a" {
                varied.push(k);
                constants.push(0.0);
                continue;
            }
            let value = named
                .iter()
                .find(|(n, _)| n == name)
                .map(|&(_, v)| v)
                .ok_or_else(|| {
                    let names: Vec<&str> = ["x", "a"]
                        .into_iter()
                        .chain(named.iter().map(|(n, _)| *n))
                        .collect();
                    say(
                        "theory-unknown-name",
                        &[("name", name), ("names", &names.join(", "))],
                    )
                })?;
            constants.push(value);
        }
        Ok(Self {
            expression,
            constants,
            varied,
            angle: setting.is_angle(),
        })
    }

    /// The law's value at the varied value `x` (in the file's unit).
    pub fn at(&self, x: f64) -> f64 {
        use exmex::Express as _;
        let x = if self.angle { x.to_radians() } else { x };
        let mut values = self.constants.clone();
        for &k in &self.varied {
            values[k] = x;
        }
        self.expression.eval(&values).unwrap_or(f64::NAN)
    }
}

/// exmex's operators on floats, and `K`.
#[derive(Clone, Debug)]
struct TheoryOps;

impl exmex::MakeOperators<f64> for TheoryOps {
    fn make<'a>() -> Vec<exmex::Operator<'a, f64>> {
        let mut operators = exmex::FloatOpsFactory::<f64>::make();
        operators.push(exmex::Operator::make_unary("K", elliptic_k));
        operators
    }
}

/// The complete elliptic integral of the first kind K(k), |k| < 1, by the
/// arithmetic–geometric mean (quadratic convergence: 30 rounds are past f64's digits).
pub fn elliptic_k(k: f64) -> f64 {
    if k.abs() >= 1.0 || k.is_nan() {
        return f64::NAN;
    }
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}
