//! A screenshot test inside `cargo test`, the way a user of the library
//! writes one (copy the test into your crate's `tests/`):
//!
//!     cargo test --example screenshot_test
//!
//! It renders the example scene, compares it with its golden within a
//! tolerance, and on failure leaves `spinner_half_turn.actual.png` and
//! `spinner_half_turn.diff.png` in `target/screenshots/`.
//! `ANIMED_UPDATE=1 cargo test --example screenshot_test` accepts a
//! changed picture.

fn main() {
    println!("run me with: cargo test --example screenshot_test");
}

#[cfg(test)]
mod tests {
    use animed::check::{verify, Options};
    use animed::{Allowance, RenderSpec, Tolerance};

    #[test]
    fn spinner_half_turn() -> Result<(), animed::Error> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let scene = animed::load(root.join("examples/suite/spinner.wrl"))?;
        let picture = animed::render(&scene, &RenderSpec::new(160, 120).at(0.5))?;
        let verdict = verify(
            &picture,
            &root.join("examples/suite/goldens/turn@0.5.png"),
            "spinner_half_turn",
            &Tolerance::new(2, Allowance::Fraction(0.001)),
            &Options::new(root.join("target/screenshots")),
        )?;
        assert!(
            !verdict.status.is_failure(),
            "{:?}: {:?}",
            verdict.status,
            verdict.comparison.map(|c| c.summary())
        );
        Ok(())
    }
}
