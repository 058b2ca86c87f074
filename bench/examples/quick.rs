use bandnoise_bench::{IMPLEMENTATIONS, N, layout, peer_function, workload};
use std::time::Instant;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let l = layout(&args[1]).unwrap();
    let mut out = vec![0.0f32; N * N];
    for function in &args[2..] {
        let peer = peer_function(function);
        let peers: Vec<_> = IMPLEMENTATIONS[2..]
            .iter()
            .filter_map(|&i| workload(peer, i, l).map(|w| (i, w)))
            .collect();
        let ours =
            [IMPLEMENTATIONS[0], IMPLEMENTATIONS[1]].map(|i| workload(function, i, l).unwrap());
        let mut r = [vec![], vec![]];
        let mut names = std::collections::BTreeMap::new();
        for round in 0..41 {
            let mut best = (f64::INFINITY, "");
            for (name, p) in &peers {
                let t = Instant::now();
                p(32, &mut out);
                let t = t.elapsed().as_secs_f64();
                if t < best.0 {
                    best = (t, name);
                }
            }
            *names.entry(best.1).or_insert(0) += 1;
            for (k, o) in ours.iter().enumerate() {
                let t = Instant::now();
                o(32, &mut out);
                let t = t.elapsed().as_secs_f64();
                if round > 0 {
                    r[k].push(t / best.0);
                }
            }
        }
        for v in &mut r {
            v.sort_by(f64::total_cmp);
        }
        println!(
            "{function} {}: point {:.2} batch {:.2} (fastest {:?})",
            l.name, r[0][20], r[1][20], names
        );
    }
}
