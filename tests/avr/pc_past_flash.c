/* A thread that frees more stack than it took returns through bytes
 * nobody wrote: the kernel's stack paint, 0xE7 0xE7, a return address of
 * word 0xE7E7, byte 0x1CFCE, far past the ATmega328P's 32 KB of flash.
 * openswarm-sim read the next instruction there before simavr's own
 * bounds check and died of SIGSEGV (exit 139); it now ends the run as a
 * crash, exit 3, naming the robot, the PC and the firmware
 * (avr.pc_past_flash). The paint's bytes are pushed here by hand, so the
 * address does not depend on the kernel's layout. */
int main(void) {
    __asm__ volatile("ldi r24, 0xE7\n\t"
                     "push r24\n\t"
                     "push r24\n\t"
                     "ret\n\t" ::: "r24");
    return 0;
}
