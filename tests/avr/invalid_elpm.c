/* ELPM r24, Z+ (0x9187), an extended flash read, on the ATmega328P, which
 * has no RAMPZ for it: simavr 1.6 logs an invalid opcode and then carries
 * the read out anyway, taking r0 (data address 0, where a RAMPZ address
 * of none points) as the top byte of the address: with r0 = 0xFF it read
 * 16 MB past the simulator's flash and died of SIGSEGV (found by
 * sim/fuzz/fuzz_sim_firmware). openswarm-sim now stops the robot before
 * the instruction and fails the run as a crash naming the opcode and its
 * address (avr.invalid_elpm). avr-as refuses ELPM for this MCU: the
 * opcode is written as a word. */
int main(void) {
    __asm__ volatile("ldi r24, 0xFF\n\t"
                     "mov r0, r24\n\t"
                     "ldi r30, 0xFF\n\t"
                     "ldi r31, 0xFF\n\t"
                     ".word 0x9187\n\t" ::: "r0", "r24", "r30", "r31");
    return 0;
}
