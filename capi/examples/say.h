/* The examples' output: the host's stdout, or a debugger's console through Arm semihosting
 * on firmware (compiled with -DBN_FIRMWARE; firmware/startup.c). Just what the examples
 * print: strings, unsigned decimals and 32-bit hex, so firmware needs no printf. */
#ifndef BN_SAY_H
#define BN_SAY_H

#include <stdint.h>

#ifdef BN_FIRMWARE
/* Semihosting SYS_WRITE0: the debugger (QEMU) prints a NUL-terminated string. */
static void say(const char *s) {
    register uint32_t op __asm__("r0") = 0x04;
    register const char *arg __asm__("r1") = s;
    __asm__ volatile("bkpt 0xAB" : "+r"(op) : "r"(arg) : "memory");
}
#else
#include <stdio.h>
static void say(const char *s) { fputs(s, stdout); }
#endif

static void say_uint(uint32_t v) {
    char buf[11];
    int i = 10;
    buf[i] = 0;
    do {
        buf[--i] = (char)('0' + v % 10);
        v /= 10;
    } while (v != 0);
    say(&buf[i]);
}

static void say_hex(uint32_t v) {
    char buf[9];
    for (int i = 7; i >= 0; i--) {
        buf[i] = "0123456789abcdef"[v & 15];
        v >>= 4;
    }
    buf[8] = 0;
    say(buf);
}

#endif
