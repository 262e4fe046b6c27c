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
        let mut words = rest.split_whitespace();
        let value = words.next().ok_or_else(malformed)?;
        let direction = match words.next() {
            None => Direction::Either,
            Some("up") => Direction::Up,
            Some("down") => Direction::Down,
            Some(_) => return Err(malformed()),
        };
        if words.next().is_some() {
            return Err(malformed());
        }
        let value = value
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| {
                newtonlab_i18n::tr_text("event-value", &[("text", text.trim()), ("value", value)])
            })?;
        Ok(Self {
            quantity: Quantity::parse(quantity.trim())?,
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
}
