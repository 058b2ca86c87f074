//! What a description costs: every noise of [`Base::ALL`] in each of its dimensions from 2 to
//! 4, built from a [`Spec`] with its defaults, sampled point by point and with
//! [`Noise::fill_grid`](bandnoise::Noise::fill_grid) over the user's grid (the `off-lattice`
//! layout of `bandnoise_bench`), against the typed noise where the peer benchmark has it (the
//! workload `<name>-<D>d`), in interleaved rounds: the table gives ns/sample of the spec and
//! the median ratio spec / typed (1.00: the `match` per call costs nothing measurable).
//!
//! The rows come from the description, so a noise added to it is measured here without a
//! change. `cargo bench -p bandnoise-bench --bench spec`; under `cargo test` (or with `-- --test`)
//! each workload runs once, unmeasured, and no table is printed.

use bandnoise::spec::{Base, Spec};
use bandnoise_bench::{Layout, N, Run, layout, measuring, quantile, seconds, workload};

/// Rounds of the paired measurement.
const ROUNDS: usize = 31;

/// Grid rows every workload fills in a round.
const ROWS: usize = 16;

/// The spec of `base` with its defaults, built in `dims` dimensions, as a point or batch
/// workload on `l`; `None` where the base has no such dimension.
fn spec_workload(base: Base, dims: usize, batch: bool, l: Layout) -> Option<Run> {
    let spec = Spec::new(base, 0);
    macro_rules! run {
        ($d:literal) => {{
            let noise = spec.build::<$d>().ok()?;
            if batch {
                l.batch::<_, $d>(noise)
            } else {
                l.point::<_, $d>(noise)
            }
        }};
    }
    Some(match dims {
        2 => run!(2),
        3 => run!(3),
        4 => run!(4),
        _ => return None,
    })
}

fn main() {
    let test = !measuring();
    let l = layout("off-lattice").expect("the bench's user grid");
    let mut out = vec![0.0f32; N * N];
    if !test {
        println!(
            "\nspec-built noise, layout {} (step {}, origin {:?}): ns/sample and the median \
             [quartiles] of spec / typed over {ROUNDS} interleaved rounds of {ROWS} rows",
            l.name, l.step, l.origin
        );
        println!("| noise | point ns | point / typed | batch ns | batch / typed |");
        println!("|---|---|---|---|---|");
    }
    for base in Base::ALL {
        for dims in 2..=4 {
            let typed_name = format!("{}-{dims}d", base.name());
            let mut cells = Vec::new();
            for (batch, implementation) in [(false, "bandnoise"), (true, "bandnoise-batch")] {
                let Some(spec) = spec_workload(base, dims, batch, l) else {
                    continue;
                };
                if test {
                    spec(1, &mut out);
                    continue;
                }
                let typed = workload(&typed_name, implementation, l);
                let (mut ns, mut ratios) = (Vec::new(), Vec::new());
                // One round unmeasured, to warm caches and branch predictors.
                for round in 0..=ROUNDS {
                    let t = seconds(&spec, ROWS, &mut out);
                    let typed_t = typed.as_ref().map(|run| seconds(run, ROWS, &mut out));
                    if round > 0 {
                        ns.push(t * 1e9 / (ROWS * N) as f64);
                        ratios.extend(typed_t.map(|u| t / u));
                    }
                }
                let ratio = if ratios.is_empty() {
                    "–".to_string()
                } else {
                    let (q1, m, q3) = (
                        quantile(&mut ratios, 0.25),
                        quantile(&mut ratios, 0.5),
                        quantile(&mut ratios, 0.75),
                    );
                    format!("{m:.2} [{q1:.2}–{q3:.2}]")
                };
                cells.push(format!("{:.2} | {ratio}", quantile(&mut ns, 0.5)));
            }
            if !cells.is_empty() && !test {
                println!("| {typed_name} | {} |", cells.join(" | "));
            }
        }
    }
}
