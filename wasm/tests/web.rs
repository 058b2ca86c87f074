//! The wrapper in a real browser (headless Chromium through wasm-bindgen-test-runner):
//! `cargo test -p bandnoise-wasm --target wasm32-unknown-unknown`.
#![cfg(target_arch = "wasm32")]

use bandnoise_wasm::{BadField, Demo, Params};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

wasm_bindgen_test_configure!(run_in_browser);

const BANDS: [f32; 8] = [0.0, 0.0, 0.2, 0.5, 1.0, 0.5, 0.25, 0.12];

/// What the page sends, with its defaults; a test changes a field and calls `build`.
#[derive(Clone, Copy)]
struct Args<'a> {
    kind: &'a str,
    number: &'a str,
    seed: f64,
    zoom: f64,
    pan: [f64; 2],
    time: f64,
    period: f64,
    fractal: &'a str,
    octaves: f64,
    bands: &'a [f32],
    tiling: &'a str,
    density: f64,
    kernel: &'a str,
    covariance: &'a str,
    frequency: f64,
    bandwidth: f64,
    direction: [f64; 2],
    orientation: &'a str,
    envelope: &'a str,
    texture: [f64; 2],
    warp: f64,
    projected: bool,
    filtered: bool,
    infinite: bool,
}

const ARGS: Args = Args {
    kind: "perlin",
    number: "f32",
    seed: 3.0,
    zoom: 32.0,
    pan: [0.5, -1.5],
    time: 0.25,
    period: 0.0,
    fractal: "none",
    octaves: 6.0,
    bands: &BANDS,
    tiling: "blended",
    density: 10.0,
    kernel: "cosine",
    covariance: "low-pass",
    frequency: 1.0,
    bandwidth: 0.8,
    direction: [1.0, 0.0],
    orientation: "anisotropic",
    envelope: "hann",
    texture: [f64::NAN, f64::NAN],
    warp: 0.0,
    projected: false,
    filtered: false,
    infinite: false,
};

impl Args<'_> {
    fn build(self) -> Result<Params, String> {
        self.refused().map_err(|e| e.message())
    }

    fn refused(self) -> Result<Params, BadField> {
        Params::new(
            self.kind,
            self.number,
            self.seed,
            self.zoom,
            self.pan[0],
            self.pan[1],
            self.time,
            self.period,
            self.fractal,
            self.octaves,
            1.99,
            0.5,
            self.bands,
            "gaussian",
            self.tiling,
            self.density,
            self.kernel,
            self.covariance,
            self.frequency,
            self.bandwidth,
            self.direction[0],
            self.direction[1],
            self.orientation,
            self.envelope,
            &self.texture,
            self.warp,
            self.projected,
            self.filtered,
            self.infinite,
            "grey",
        )
    }
}

fn params(kind: &str, number: &str) -> Result<Params, String> {
    Args {
        kind,
        number,
        ..ARGS
    }
    .build()
}

fn canvas() -> CanvasRenderingContext2d {
    let doc = web_sys::window().unwrap().document().unwrap();
    let c: HtmlCanvasElement = doc.create_element("canvas").unwrap().dyn_into().unwrap();
    c.set_width(64);
    c.set_height(64);
    c.get_context("2d").unwrap().unwrap().dyn_into().unwrap()
}

/// The RGBA pixels of a 64² frame of `args`, drawn on `ctx`.
fn pixels(ctx: &CanvasRenderingContext2d, args: Args) -> Vec<u8> {
    let mut demo = Demo::new(64).unwrap();
    demo.render(&args.build().unwrap());
    demo.draw(ctx).unwrap();
    ctx.get_image_data(0.0, 0.0, 64.0, 64.0).unwrap().data().0
}

#[wasm_bindgen_test]
fn every_noise_renders_and_draws() {
    let mut demo = Demo::new(64).unwrap();
    let ctx = canvas();
    let names = bandnoise_wasm::kinds();
    let kinds: Vec<&str> = names.split(' ').collect();
    // Every noise of the description: the 24 with a 3D form and flow noise.
    assert_eq!(kinds.len(), 25, "{kinds:?}");
    for kind in kinds {
        for number in ["f32", "fixed"] {
            demo.render(&params(kind, number).unwrap());
            assert!(demo.std_dev() > 0.01, "{kind} {number} is flat");
            demo.draw(&ctx).unwrap();
            demo.draw_spectrum(&ctx).unwrap();
            let pixels = ctx.get_image_data(0.0, 0.0, 64.0, 64.0).unwrap().data().0;
            assert!(
                pixels.chunks(4).any(|p| p[0] != pixels[0]),
                "{kind}: uniform image"
            );
            // Nearly every value lies within ±4σ of the mean; not for polka dots, two levels
            // whose rarer one (the dots, covering p of the frame) lies (1 − p)/√(p(1 − p))
            // standard deviations out: beyond 4σ when p < 1/17 (about 5% of this view).
            let counted = demo.histogram().iter().sum::<u32>();
            assert!(
                kind == "polka-dots" || (64 * 64 * 98 / 100..=64 * 64).contains(&counted),
                "{kind}: {counted}"
            );
        }
    }
}

#[wasm_bindgen_test]
fn fixed_point_and_f32_give_nearly_the_same_frame() {
    let (mut a, mut b) = (Demo::new(32).unwrap(), Demo::new(32).unwrap());
    a.render(&params("perlin", "f32").unwrap());
    b.render(&params("perlin", "fixed").unwrap());
    assert!((a.mean() - b.mean()).abs() < 1e-3 && (a.std_dev() - b.std_dev()).abs() < 1e-3);
}

/// A period, a fractal sum and projection render too.
#[wasm_bindgen_test]
fn periodic_fractal_and_projected_noise_render() {
    let mut demo = Demo::new(32).unwrap();
    for args in [
        Args {
            period: 4.0,
            fractal: "fbm",
            ..ARGS
        },
        Args {
            kind: "multiband",
            projected: true,
            fractal: "ridged",
            octaves: 2.0,
            ..ARGS
        },
        Args {
            kind: "wavelet",
            number: "fixed",
            projected: true,
            ..ARGS
        },
        Args {
            kind: "multiband",
            tiling: "varied",
            ..ARGS
        },
        Args {
            kind: "wavelet",
            number: "fixed",
            tiling: "periodic",
            ..ARGS
        },
    ] {
        demo.render(&args.build().unwrap());
        assert!(demo.std_dev() > 0.01, "{} is flat", args.kind);
    }
    // A period of 4 cells: the frame (zoom 32, 32 pixels: one cell) at pan x and x + 4 is the
    // same.
    let (mut a, mut b) = (Demo::new(32).unwrap(), Demo::new(32).unwrap());
    let periodic = Args {
        period: 4.0,
        ..ARGS
    };
    a.render(&periodic.build().unwrap());
    b.render(
        &Args {
            pan: [4.5, -1.5],
            ..periodic
        }
        .build()
        .unwrap(),
    );
    assert_eq!(a.mean().to_bits(), b.mean().to_bits());
    assert_eq!(a.std_dev().to_bits(), b.std_dev().to_bits());
}

/// Filtering by the pixel's footprint fades the bands finer than a pixel: at 2 pixels per unit
/// the default bands 2–4 (2–8 coefficients per pixel) alias in a point-sampled frame and fade
/// in a filtered one, so its deviation drops; fractal sums and one band filter too.
#[wasm_bindgen_test]
fn filtering_fades_what_a_pixel_cannot_show() {
    let mut demo = Demo::new(64).unwrap();
    for number in ["f32", "fixed"] {
        let aliased = Args {
            kind: "multiband",
            number,
            zoom: 2.0,
            ..ARGS
        };
        demo.render(&aliased.build().unwrap());
        let plain = demo.std_dev();
        demo.render(
            &Args {
                filtered: true,
                ..aliased
            }
            .build()
            .unwrap(),
        );
        let filtered = demo.std_dev();
        assert!(
            filtered < 0.8 * plain && filtered > 0.05,
            "{number}: σ {plain} plain, {filtered} filtered"
        );
    }
    for args in [
        Args {
            kind: "wavelet",
            zoom: 0.5,
            ..ARGS
        },
        Args {
            fractal: "fbm",
            octaves: 8.0,
            zoom: 4.0,
            ..ARGS
        },
    ] {
        demo.render(&args.build().unwrap());
        let plain = demo.std_dev();
        demo.render(
            &Args {
                filtered: true,
                ..args
            }
            .build()
            .unwrap(),
        );
        assert!(
            demo.std_dev() < plain && demo.std_dev() > 0.01,
            "{} {}: σ {plain} plain, {} filtered",
            args.kind,
            args.fractal,
            demo.std_dev()
        );
    }
}

/// Infinite zoom: 2¹⁰ times closer, multiband noise looks as it did (its deviation over the
/// frame stays near 1), where the plain noise is a smooth fraction of one coefficient.
#[wasm_bindgen_test]
fn infinite_zoom_keeps_the_detail() {
    let mut demo = Demo::new(64).unwrap();
    for number in ["f32", "fixed"] {
        let infinite = Args {
            kind: "multiband",
            number,
            infinite: true,
            ..ARGS
        };
        let mut sigma = [0.0; 2];
        for (i, zoom) in [32.0, 32.0 * 1024.0].into_iter().enumerate() {
            demo.render(&Args { zoom, ..infinite }.build().unwrap());
            sigma[i] = demo.std_dev();
        }
        assert!(
            sigma.iter().all(|s| (0.5..1.5).contains(s)),
            "{number}: σ {sigma:?}"
        );
        demo.render(
            &Args {
                zoom: 32.0 * 1024.0,
                infinite: false,
                ..infinite
            }
            .build()
            .unwrap(),
        );
        assert!(demo.std_dev() < 0.1, "{number}: plain σ {}", demo.std_dev());
    }
}

#[wasm_bindgen_test]
fn bad_parameters_are_refused_with_a_message() {
    let refused = |args: Args, needle: &str| {
        let msg = args.build().err().unwrap_or_default();
        assert!(msg.contains(needle), "{needle}: {msg}");
    };
    refused(
        Args {
            kind: "nope",
            ..ARGS
        },
        "unknown noise kind",
    );
    refused(
        Args {
            seed: f64::NAN,
            ..ARGS
        },
        "seed",
    );
    refused(Args { zoom: -1.0, ..ARGS }, "zoom");
    refused(
        Args {
            pan: [1e300, 0.0],
            ..ARGS
        },
        "pan",
    );
    refused(
        Args {
            fractal: "fbm",
            octaves: 99.0,
            ..ARGS
        },
        "octaves",
    );
    refused(
        Args {
            kind: "multiband",
            bands: &[0.0; 8],
            ..ARGS
        },
        "band weight is zero",
    );
    refused(
        Args {
            period: 1e5,
            ..ARGS
        },
        "period",
    );
    refused(
        Args {
            period: f64::NAN,
            ..ARGS
        },
        "period",
    );
    refused(
        Args {
            kind: "wavelet",
            period: 8.0,
            ..ARGS
        },
        "not on the integer lattice",
    );
    refused(
        Args {
            projected: true,
            ..ARGS
        },
        "projection applies",
    );
    refused(
        Args {
            kind: "wavelet",
            tiling: "tiled",
            ..ARGS
        },
        "tiling must be",
    );
    refused(
        Args {
            kind: "sparse",
            density: 500.0,
            ..ARGS
        },
        "impulse density 500 must be",
    );
    refused(
        Args {
            kind: "sparse",
            density: f64::NAN,
            ..ARGS
        },
        "density",
    );
    refused(
        Args {
            kernel: "gauss",
            ..ARGS
        },
        "kernel must be",
    );
    refused(
        Args {
            filtered: true,
            ..ARGS
        },
        "filtering applies",
    );
    refused(
        Args {
            kind: "wavelet",
            projected: true,
            filtered: true,
            ..ARGS
        },
        "not projected",
    );
    refused(
        Args {
            kind: "wavelet",
            infinite: true,
            ..ARGS
        },
        "infinite zoom applies to multiband",
    );
    refused(
        Args {
            kind: "multiband",
            fractal: "fbm",
            infinite: true,
            ..ARGS
        },
        "infinite zoom is multiband noise on its own",
    );
    assert!(Demo::new(100).is_err());
}

/// Sparse noise's controls: the density and the kernel change the image (a sparser noise has
/// a heavier-tailed histogram: more of it beyond 2σ), and other noises ignore them.
#[wasm_bindgen_test]
fn sparse_density_and_kernel_change_the_image() {
    let ctx = canvas();
    let render = |args: Args| {
        let mut demo = Demo::new(64).unwrap();
        demo.render(&args.build().unwrap());
        demo.draw(&ctx).unwrap();
        let pixels = ctx.get_image_data(0.0, 0.0, 64.0, 64.0).unwrap().data().0;
        (pixels, demo.histogram())
    };
    let sparse = Args {
        kind: "sparse",
        zoom: 8.0,
        ..ARGS
    };
    let (dense, dense_hist) = render(sparse);
    let (lumpy, lumpy_hist) = render(Args {
        density: 1.0,
        ..sparse
    });
    let (peachey, _) = render(Args {
        kernel: "catmull-rom",
        ..sparse
    });
    assert!(dense != lumpy, "the density changes the image");
    assert!(dense != peachey, "the kernel changes the image");
    // Bins span ±4σ: the outer quarters are beyond 2σ.
    let tails = |h: &[u32]| {
        let q = h.len() / 4;
        h[..q].iter().chain(&h[h.len() - q..]).sum::<u32>()
    };
    assert!(
        tails(&lumpy_hist) > tails(&dense_hist),
        "{lumpy_hist:?} {dense_hist:?}"
    );
    // Ignored by the other noises.
    let other = Args {
        density: 2.0,
        kernel: "catmull-rom",
        ..ARGS
    };
    assert!(render(ARGS).0 == render(other).0, "perlin ignores them");
}

/// Wiener noise's covariance changes the image, a bad one is refused, and other noises ignore
/// it.
#[wasm_bindgen_test]
fn wiener_covariance_changes_the_image() {
    let ctx = canvas();
    let render = |args: Args| pixels(&ctx, args);
    let wiener = Args {
        kind: "wiener",
        zoom: 8.0,
        ..ARGS
    };
    let low = render(wiener);
    let band = render(Args {
        covariance: "band-pass",
        ..wiener
    });
    assert!(low != band, "the covariance changes the image");
    assert!(
        render(ARGS)
            == render(Args {
                covariance: "band-pass",
                ..ARGS
            }),
        "perlin ignores it"
    );
    let e = Args {
        covariance: "high-pass",
        ..wiener
    }
    .build()
    .unwrap_err();
    assert!(e.contains("covariance must be"), "{e}");
}

/// The textures' two settings and the domain warp change the image; empty settings are the
/// texture's defaults; bad values are refused with the core's reason.
#[wasm_bindgen_test]
fn texture_settings_and_warp_change_the_image() {
    let ctx = canvas();
    let render = |args: Args| pixels(&ctx, args);
    let wood = Args {
        kind: "wood",
        zoom: 8.0,
        ..ARGS
    };
    let plain = render(wood);
    assert!(
        plain
            == render(Args {
                texture: [2.0, 0.3],
                ..wood
            }),
        "the defaults, written out, are the defaults"
    );
    let rings = render(Args {
        texture: [5.0, f64::NAN],
        ..wood
    });
    assert!(plain != rings, "the rings setting changes the image");
    assert!(
        render(ARGS)
            == render(Args {
                texture: [5.0, 1.0],
                ..ARGS
            }),
        "perlin ignores texture settings"
    );
    let warped = render(Args { warp: 0.8, ..ARGS });
    assert!(render(ARGS) != warped, "a warp changes the image");
    let e = Args {
        kind: "polka-dots",
        texture: [7.0, f64::NAN],
        ..ARGS
    }
    .build()
    .unwrap_err();
    assert!(e.contains("texture radius"), "{e}");
    let e = Args {
        warp: 2000.0,
        ..ARGS
    }
    .build()
    .unwrap_err();
    assert!(e.contains("warp amplitude 2000"), "{e}");
    let e = Args {
        warp: 0.5,
        period: 8.0,
        ..ARGS
    }
    .build()
    .unwrap_err();
    assert!(e.contains("cannot be combined"), "{e}");
}

/// Gabor noise's controls: the spectrum view's lobes sit at the frequency along the direction
/// and move with them; the variants and the envelope change the image; bad settings are
/// refused with the core's reason; other noises ignore them.
#[wasm_bindgen_test]
fn gabor_lobes_follow_the_controls() {
    // The brightest spectrum bin outside the centre, as an offset from DC (the view is 64²,
    // DC at (32, 32)): with zoom 8, F₀ cycles per unit are 8·F₀ bins from DC.
    let peak = |args: Args| {
        let mut demo = Demo::new(64).unwrap();
        demo.render(&args.build().unwrap());
        demo.draw_spectrum(&canvas()).unwrap();
        let spectrum = demo.spectrum();
        let mut best = (0u8, (0i32, 0i32));
        for (i, &v) in spectrum.iter().enumerate() {
            let (x, y) = ((i % 64) as i32 - 32, (i / 64) as i32 - 32);
            if x * x + y * y > 9 && v > best.0 {
                best = (v, (x, y));
            }
        }
        (best.1, spectrum)
    };
    let gabor = Args {
        kind: "gabor",
        zoom: 8.0,
        bandwidth: 0.25,
        ..ARGS
    };
    let ((x, y), along_x) = peak(gabor);
    assert!(
        (x.abs() - 8).abs() <= 1 && y.abs() <= 1,
        "F0 1 along x: ({x}, {y})"
    );
    let ((x, y), _) = peak(Args {
        frequency: 2.0,
        direction: [0.0, 1.0],
        ..gabor
    });
    assert!(
        x.abs() <= 1 && (y.abs() - 16).abs() <= 1,
        "F0 2 along y: ({x}, {y})"
    );
    let (_, isotropic) = peak(Args {
        orientation: "isotropic",
        ..gabor
    });
    assert!(along_x != isotropic, "the orientation changes the spectrum");
    let (_, truncated) = peak(Args {
        envelope: "truncated",
        ..gabor
    });
    assert!(along_x != truncated, "the envelope changes the image");
    for (bad, why) in [
        (
            Args {
                bandwidth: 0.0,
                ..gabor
            },
            "bandwidth",
        ),
        (
            Args {
                frequency: 100.0,
                ..gabor
            },
            "frequency",
        ),
        (
            Args {
                direction: [0.0, 0.0],
                ..gabor
            },
            "direction",
        ),
        (
            Args {
                orientation: "sideways",
                ..gabor
            },
            "orientation must be",
        ),
        (
            Args {
                envelope: "square",
                ..gabor
            },
            "envelope must be",
        ),
    ] {
        let e = bad.build().unwrap_err();
        assert!(e.contains(why), "{e}");
    }
    // Ignored by the other noises (the same frame).
    let (_, plain) = peak(ARGS);
    let (_, other) = peak(Args {
        frequency: 3.0,
        direction: [0.0, 1.0],
        orientation: "isotropic",
        ..ARGS
    });
    assert!(plain == other, "perlin ignores them");
}

/// Each refusal names the page's field it came from (the id of its element), so the page
/// shows the message next to it; the core's refusals too, by what they refuse.
#[wasm_bindgen_test]
fn refusals_name_their_field() {
    let fbm = Args {
        fractal: "fbm",
        ..ARGS
    };
    let gabor = Args {
        kind: "gabor",
        ..ARGS
    };
    let dots = Args {
        kind: "polka-dots",
        ..ARGS
    };
    let cases = [
        (
            Args {
                kind: "nope",
                ..ARGS
            },
            "kind",
        ),
        (
            Args {
                number: "f16",
                ..ARGS
            },
            "number",
        ),
        (Args { seed: -1.0, ..ARGS }, "seed"),
        (Args { zoom: 0.0, ..ARGS }, "zoom"),
        (
            Args {
                zoom: f64::NAN,
                ..ARGS
            },
            "zoom",
        ),
        (
            Args {
                pan: [f64::INFINITY, 0.0],
                ..ARGS
            },
            "",
        ),
        (
            Args {
                time: f64::NAN,
                ..ARGS
            },
            "time",
        ),
        (
            Args {
                period: 0.5,
                ..ARGS
            },
            "period",
        ),
        (
            Args {
                fractal: "brown",
                ..ARGS
            },
            "fractal",
        ),
        (
            Args {
                octaves: 40.0,
                ..fbm
            },
            "octaves",
        ),
        (
            Args {
                kind: "wavelet",
                period: 4.0,
                ..ARGS
            },
            "period",
        ),
        (
            Args {
                tiling: "random",
                ..ARGS
            },
            "tiling",
        ),
        (
            Args {
                kind: "sparse",
                density: 1e6,
                ..ARGS
            },
            "density",
        ),
        (
            Args {
                kernel: "box",
                ..ARGS
            },
            "kernel",
        ),
        (
            Args {
                covariance: "high-pass",
                ..ARGS
            },
            "covariance",
        ),
        (
            Args {
                frequency: 1e4,
                ..gabor
            },
            "frequency",
        ),
        (
            Args {
                bandwidth: 1e4,
                ..gabor
            },
            "bandwidth",
        ),
        (
            Args {
                direction: [0.0, 0.0],
                ..gabor
            },
            "angle",
        ),
        (
            Args {
                orientation: "sideways",
                ..ARGS
            },
            "orientation",
        ),
        (
            Args {
                envelope: "square",
                ..ARGS
            },
            "envelope",
        ),
        (
            Args {
                texture: [7.0, f64::NAN],
                ..dots
            },
            "texture1",
        ),
        (
            Args {
                texture: [f64::NAN, 7.0],
                ..dots
            },
            "texture2",
        ),
        (
            Args {
                kind: "multiband",
                bands: &[0.0; 8],
                ..ARGS
            },
            "bands",
        ),
        (
            Args {
                warp: 2000.0,
                ..ARGS
            },
            "warp",
        ),
        (
            Args {
                projected: true,
                ..ARGS
            },
            "projected",
        ),
        (
            Args {
                filtered: true,
                ..ARGS
            },
            "filtered",
        ),
        (
            Args {
                infinite: true,
                ..ARGS
            },
            "infinite",
        ),
    ];
    for (args, field) in cases {
        let e = args.refused().unwrap_err();
        assert_eq!(e.field(), field, "{}", e.message());
        assert!(!e.message().is_empty());
    }
}

/// The sphere view: off the sphere the page's background, on it noise whose statistics leave
/// the background out; a wavelet band projected onto the tangent planes differs from its
/// slices, in f32 and fixed point; other noises are sliced whatever the projection.
#[wasm_bindgen_test]
fn the_sphere_view_slices_or_projects() {
    let ctx = canvas();
    let sphere = |args: Args| {
        let mut demo = Demo::new(64).unwrap();
        demo.render_sphere(&args.build().unwrap());
        assert!(
            demo.std_dev() > 0.05 && demo.mean().abs() < 1.0,
            "{}",
            demo.std_dev()
        );
        demo.draw(&ctx).unwrap();
        ctx.get_image_data(0.0, 0.0, 64.0, 64.0).unwrap().data().0
    };
    for number in ["f32", "fixed"] {
        let band = Args {
            kind: "wavelet",
            number,
            zoom: 8.0,
            ..ARGS
        };
        let sliced = sphere(band);
        assert_eq!(&sliced[..3], &[250, 250, 250], "a corner is background");
        let projected = sphere(Args {
            projected: true,
            ..band
        });
        assert!(
            sliced != projected,
            "{number}: projected differs from sliced"
        );
    }
    let perlin = sphere(ARGS);
    assert_eq!(&perlin[..3], &[250, 250, 250]);
}
