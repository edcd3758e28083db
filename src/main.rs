fn main() {
    std::process::exit(animed::internals::cli::run());
}
