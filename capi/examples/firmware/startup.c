/* A bare Cortex-M start for the C examples under QEMU, with no C library: the vector table,
 * the reset handler (FPU on for the Cortex-M4F, .data copied, .bss zeroed), main, and the
 * verdict as QEMU's exit status through Arm semihosting (SYS_EXIT: ApplicationExit is 0,
 * anything else 1). Linked with microbit.ld (Cortex-M0) or an386.ld (Cortex-M4F). */
#include <stdint.h>

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);

static void semihosting_exit(int ok) {
    register uint32_t op __asm__("r0") = 0x18; /* SYS_EXIT */
    register uint32_t reason __asm__("r1") = ok ? 0x20026u : 0x20023u;
    __asm__ volatile("bkpt 0xAB" : "+r"(op) : "r"(reason) : "memory");
    for (;;) {
    }
}

static void write0(const char *s) {
    register uint32_t op __asm__("r0") = 0x04; /* SYS_WRITE0 */
    register const char *arg __asm__("r1") = s;
    __asm__ volatile("bkpt 0xAB" : "+r"(op) : "r"(arg) : "memory");
}

void reset(void) {
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11, before any floating-point instruction. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    const uint32_t *from = &_sidata;
    for (uint32_t *to = &_sdata; to < &_edata;) {
        *to++ = *from++;
    }
    for (uint32_t *to = &_sbss; to < &_ebss;) {
        *to++ = 0;
    }
    semihosting_exit(main() == 0);
}

static void fault(void) {
    write0("fault\n");
    semihosting_exit(0);
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))&_estack, reset, fault, fault, fault, fault, fault, 0, 0, 0, 0,
    fault, fault, 0, fault, fault,
};
