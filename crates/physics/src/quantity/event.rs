//! An event as a scene, a series or a command line writes it: a quantity crossing a value
//! (`Bob.vx crosses 0 down`). Locating one in a run is [`crate::events`]' work.

use std::fmt;

use super::Quantity;

/// Which way a crossing must go.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Either way.
    Either,
    /// From below the value to it or above.
    Up,
    /// From above the value to it or below.
    Down,
}

/// `QUANTITY crosses VALUE`, optionally `up` or `down`.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    /// What crosses.
    pub quantity: Quantity,
    /// The value crossed, in the quantity's SI unit (degrees for an angle).
    pub value: f64,
    /// Which way.
    pub direction: Direction,
}

impl Event {
    /// Reads `QUANTITY crosses VALUE [up|down]` (`Ball.y crosses 0 down`). Whether the
    /// object exists is the simulation's question ([`crate::Watch::new`]).
    ///
    /// # Errors
    /// What the text should have been.
    pub fn parse(text: &str) -> Result<Self, String> {
        let malformed = || newtonlab_i18n::tr_text("event-malformed", &[("text", text.trim())]);
        let (quantity, rest) = text.trim().rsplit_once(" crosses ").ok_or_else(malformed)?;
        let rest = rest.trim();
        let (value, direction) = match rest.rsplit_once(char::is_whitespace) {
            Some((value, "up")) => (value.trim(), Direction::Up),
            Some((value, "down")) => (value.trim(), Direction::Down),
            _ => (rest, Direction::Either),
        };
        if value.is_empty() {
            return Err(malformed());
        }
        let quantity = Quantity::parse(quantity.trim())?;
        // Arithmetic and units as the inspector's fields read them (`-2*cos(60°)`,
        // `50 cm` for a position), in the quantity's own unit.
        if let Some(reason) = crate::units::too_big(value.trim()) {
            return Err(reason);
        }
        let value = crate::units::parse(value, quantity.unit())
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| {
                newtonlab_i18n::tr_text("event-value", &[("text", text.trim()), ("value", value)])
            })?;
        Ok(Self {
            quantity,
            value,
            direction,
        })
    }
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} crosses {:?}", self.quantity, self.value)?;
        match self.direction {
            Direction::Either => Ok(()),
            Direction::Up => f.write_str(" up"),
            Direction::Down => f.write_str(" down"),
        }
    }
}

impl std::str::FromStr for Event {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        Self::parse(text)
    }
}

/// Largest or smallest.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Turn {
    /// A maximum.
    Maximum,
    /// A minimum.
    Minimum,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_read_back_as_written() {
        for text in [
            "Bob.vx crosses 0.0",
            "Ball.y crosses -1.5 down",
            "rod.angle crosses 0.0 up",
        ] {
            let event = Event::parse(text).unwrap();
            assert_eq!(event.to_string(), text);
        }
        assert_eq!(
            Event::parse("  a b.x crosses 2 up ").unwrap().quantity,
            Quantity::Particle("a b".to_owned(), super::super::Of::X),
            "names may hold spaces"
        );
        for bad in [
            "",
            "Bob.vx",
            "Bob.vx crosses",
            "Bob.vx crosses zero",
            "Bob.vx crosses 0 sideways",
            "Bob.vx crosses 0 up now",
            "Bob.vx crosses inf",
            "Bob.q crosses 0",
        ] {
            assert!(Event::parse(bad).is_err(), "{bad:?} refused");
        }
    }

    /// The value takes arithmetic and units as the inspector's fields do, in the
    /// quantity's own unit; the direction is still the last word.
    #[test]
    fn an_events_value_takes_arithmetic_and_units() {
        let cases = [
            ("Bob.y crosses -2*cos(60°)", -1.0, Direction::Either),
            ("Bob.y crosses 50 cm down", 0.5, Direction::Down),
            ("Bob.vx crosses 36 km/h up", 10.0, Direction::Up),
            (
                "t crosses pi/2",
                std::f64::consts::FRAC_PI_2,
                Direction::Either,
            ),
            ("rod.angle crosses 90 - 30", 60.0, Direction::Either),
            (
                "Bob.kinetic_energy crosses sqrt(2) * 2 up",
                8_f64.sqrt(),
                Direction::Up,
            ),
        ];
        for (text, value, direction) in cases {
            let event = Event::parse(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert!(
                (event.value - value).abs() < 1e-12,
                "{text}: {}",
                event.value
            );
            assert_eq!(event.direction, direction, "{text}");
        }
        // A unit of another kind is no value of the quantity.
        assert!(Event::parse("Bob.y crosses 3 s").is_err());
    }
}
