/* bandnoise from C in a page: build a noise from its description, sample it in float and in
 * 16.16 fixed point, fill a grid, and read an error. Build (capi/README.md):
 *
 *   cargo build --release -p bandnoise-capi
 *   cc -Icapi/include capi/examples/hello.c target/release/libbandnoise_c.a -lm -o hello
 */
#include <stdio.h>

#include "bandnoise.h"

int main(void) {
    bn_noise noise; /* the noise lives here: no allocation */
    bn_error error;

    /* Any runtime description: here 5 octaves of Perlin noise's fBm. */
    if (bn_noise_init(&noise, "perlin seed=7 fbm octaves=5", 2, &error) != BN_OK) {
        fprintf(stderr, "%s\n", error.message);
        return 1;
    }
    char text[256];
    bn_noise_text(&noise, text, sizeof text);
    printf("noise: %s\n", text);

    float p[2] = {0.3f, 1.7f}, v;
    bn_sample_f32(&noise, p, &v);
    int32_t q[2] = {19661, 111411}, w; /* 0.3 and 1.7 in 16.16 (x * 65536) */
    bn_sample_fixed(&noise, q, &w);
    printf("at (0.3, 1.7): %.6f in float, %.6f in 16.16 fixed point\n", v, w / 65536.0);

    float value, gradient[2];
    bn_sample_gradient_f32(&noise, p, &value, gradient);
    printf("gradient there: (%.6f, %.6f)\n", gradient[0], gradient[1]);

    /* A 48 x 12 grid, off the lattice, drawn in characters. */
    enum { W = 48, H = 12 };
    float image[W * H];
    const float origin[2] = {0.37f, 0.61f}, step[2] = {0.13f, 0.29f};
    const size_t size[2] = {W, H};
    if (bn_fill_grid_f32(&noise, origin, step, size, image, W * H) != BN_OK) {
        return 1;
    }
    for (int y = 0; y < H; y++) {
        for (int x = 0; x < W; x++) {
            float t = image[y * W + x];
            putchar(t < -0.3f ? ' ' : t < -0.1f ? '.' : t < 0.1f ? ':' : t < 0.3f ? 'o' : '@');
        }
        putchar('\n');
    }

    /* Bad text: the status, the byte and what was expected there. */
    if (bn_noise_init(&noise, "perlin seed=7 fbm octaves=0", 2, &error) != BN_OK) {
        /* error.position is the byte (26), which the message also names. */
        printf("error %d %s\n", (int)error.status, error.message);
    }
    /* The failed init left the storage unusable, not half built. */
    printf("sampling it now: status %d\n", (int)bn_sample_f32(&noise, p, &v));
    return 0;
}
