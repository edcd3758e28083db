//! Render one frame of a scene file to a PNG with the library front door.
//!
//!     cargo run --example render_file -- examples/suite/spinner.wrl out.png 0.5
//!
//! Arguments: scene file, output PNG, optional time in seconds.

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 2 {
        eprintln!("usage: render_file SCENE OUT.png [TIME]");
        std::process::exit(2);
    }
    if let Err(e) = run(&args) {
        // Errors print as path:line:column: message.
        eprintln!("render_file: {e}");
        std::process::exit(1);
    }
}

fn run(args: &[String]) -> Result<(), Box<dyn std::error::Error>> {
    let time: f32 = match args.get(2) {
        Some(t) => t.parse()?,
        None => 0.0,
    };
    let scene = animed::load(&args[0])?;
    let spec = animed::RenderSpec::new(320, 240).at(time);
    let picture = animed::render(&scene, &spec)?;
    picture.save_png(&args[1])?;
    println!(
        "wrote {} ({}x{})",
        args[1],
        picture.width(),
        picture.height()
    );
    Ok(())
}
