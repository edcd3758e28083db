fn main() {
    std::process::exit(animed::cli::run());
}
