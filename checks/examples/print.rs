fn main() {
    let c = bandnoise_checks::checksums();
    let names = bandnoise_checks::names();
    for (i, v) in c.iter().enumerate() {
        let ty = if bandnoise_checks::is_fixed(i) {
            "I16F16"
        } else {
            "f32"
        };
        println!("{ty} {} {v:08x}", names[i]);
    }
}
