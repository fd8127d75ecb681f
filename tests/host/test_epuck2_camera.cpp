// The e-puck2's camera (ports/epuck/epuck2/drivers/camera.c, po8030.c,
// i2c_master.c) against a register model. The test plays I2C1 (START,
// address, data and STOP as the silicon answers them, recording each
// transaction) and behind it a PO8030 whose banked registers take the
// writes; then DMA2 stream 1 and the DCMI: it writes what the sensor sent
// into the DMA's memory, raises the flags and runs the handlers.
#include <gtest/gtest.h>

#include <vector>

#include "stm32f4_register_model.hpp"

extern "C" {
#include "../../ports/epuck/epuck2/drivers/camera.h"
#include "../../ports/epuck/epuck2/drivers/i2c_master.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

constexpr uint32_t TAKEN = 0xFFFFFFFFu; // DR once the silicon has the byte
constexpr unsigned W = 160, H = 120;

struct Transaction {
    std::vector<uint8_t> bytes;
    bool stopped = false;
    bool clocked = false; // the sensor's clock running at the START
};

// The I2C bus with a PO8030 (address 0x6E) on it.
struct Bus {
    bool mute = false; // the I2C block never answers
    bool nack = false; // nobody acknowledges the address
    std::vector<Transaction> log;
    uint8_t bank = 0;
    uint8_t reg[4][256] = {};
    bool address_phase = false;

    void poll() {
        stm32_i2c &i2c = epuck2_model_i2c1;
        if (mute) return;
        if (i2c.CR1 & I2C_CR1_STOP) stop();
        if (i2c.CR1 & I2C_CR1_START) {
            i2c.CR1 &= ~I2C_CR1_START;
            log.push_back({});
            log.back().clocked = epuck2_model_tim5.CR1 & TIM_CR1_CEN;
            address_phase = true;
            i2c.SR1 = I2C_SR1_SB;
        } else if (i2c.DR != TAKEN) {
            uint8_t byte = (uint8_t)i2c.DR;
            i2c.DR = TAKEN;
            if (log.empty() || log.back().stopped) {
                ADD_FAILURE() << "byte 0x" << std::hex << unsigned(byte) << " outside START..STOP";
                return;
            }
            log.back().bytes.push_back(byte);
            if (address_phase)
                i2c.SR1 = (byte == 0x6E << 1 && !nack) ? I2C_SR1_ADDR | I2C_SR1_TXE : I2C_SR1_AF;
            else
                i2c.SR1 = I2C_SR1_TXE | I2C_SR1_BTF;
            address_phase = false;
        }
    }

    // The bus idle again; a whole write (address, register, value) reaches
    // the sensor, register 0x03 of any bank choosing the bank.
    void stop() {
        epuck2_model_i2c1.CR1 &= ~I2C_CR1_STOP;
        epuck2_model_i2c1.SR1 = 0;
        if (log.empty()) return;
        Transaction &t = log.back();
        t.stopped = true;
        if (t.bytes.size() != 3 || t.bytes[0] != 0x6E << 1) return;
        if (t.bytes[1] == 0x03)
            bank = t.bytes[2];
        else
            reg[bank & 3][t.bytes[1]] = t.bytes[2];
    }

    unsigned pair(unsigned b, uint8_t r) const { return unsigned(reg[b][r]) << 8 | reg[b][r + 1]; }
};

Bus *bus;
std::vector<epuck_camera_frame> frames;
std::vector<std::vector<uint16_t>> frame_pixels;
void frame_done(const epuck_camera_frame *f) {
    frames.push_back(*f);
    frame_pixels.emplace_back(f->pixels, f->pixels + f->width * f->height);
}

const stm32_dma_stream &stream = epuck2_model_dma2.S[1];
constexpr uint32_t SHIFT = DMA_STREAM1_SHIFT;

class Camera : public ::testing::Test {
protected:
    Bus the_bus;

    void SetUp() override {
        for (stm32_gpio *g : {&epuck2_model_gpioa, &epuck2_model_gpiob, &epuck2_model_gpioc, &epuck2_model_gpioe})
            *g = {};
        epuck2_model_tim5 = {};
        epuck2_model_i2c1 = {};
        epuck2_model_i2c1.DR = TAKEN;
        epuck2_model_dcmi = {};
        epuck2_model_dma2 = {};
        epuck2_model_rcc = {};
        frames.clear();
        frame_pixels.clear();
        bus = &the_bus;
        epuck2_model_polls = 0;
        epuck2_model_silicon = [] { bus->poll(); };
        epuck2_i2c_init();
    }
    void TearDown() override { epuck2_model_silicon = nullptr; }

    bool start() {
        bool ok = epuck2_camera_init(frame_done);
        bus->poll(); // the last STOP goes out
        return ok;
    }

    // The sensor sends pixel i as v(i), high byte first; the DCMI packs the
    // bytes in arrival order, so they lie in memory as sent.
    static uint16_t v(unsigned i) { return (uint16_t)(i * 40503u + 7u); }
    static void sensor_sends_frame() {
        uint8_t *m = epuck2_camera_model_dma_memory();
        for (unsigned i = 0; i < W * H; i++) {
            m[2 * i] = (uint8_t)(v(i) >> 8);
            m[2 * i + 1] = (uint8_t)v(i);
        }
    }

    // The stream raises flags; the handler runs; LIFCR clears what it names.
    static void dma_interrupt(uint32_t flags) {
        epuck2_model_dma2.LISR |= flags << SHIFT;
        DMA2_Stream1_IRQHandler();
        epuck2_model_dma2.LISR &= ~epuck2_model_dma2.LIFCR;
        epuck2_model_dma2.LIFCR = 0;
    }
    // The last word moved: the stream stops itself (not circular).
    static void transfer_complete() {
        epuck2_model_dma2.S[1].NDTR = 0;
        epuck2_model_dma2.S[1].CR &= ~DMA_SxCR_EN;
        epuck2_model_dcmi.CR &= ~DCMI_CR_CAPTURE; // snapshot: one frame
        dma_interrupt(DMA_FLAG_TC);
    }
    // The DCMI raises flags; the handler runs; ICR clears what it names.
    static void dcmi_interrupt(uint32_t flags) {
        epuck2_model_dcmi.RIS |= flags;
        DCMI_IRQHandler();
        epuck2_model_dcmi.RIS &= ~epuck2_model_dcmi.ICR;
        epuck2_model_dcmi.ICR = 0;
    }
    static void frame_end() { dcmi_interrupt(DCMI_IT_FRAME); }
    static void whole_frame() {
        sensor_sends_frame();
        transfer_complete();
        frame_end();
    }
    static bool capturing() {
        return (epuck2_model_dcmi.CR & DCMI_CR_CAPTURE) && (stream.CR & DMA_SxCR_EN);
    }
    static void expect_rearmed() {
        EXPECT_EQ(W * H * 2 / 4, stream.NDTR) << "a whole frame's words again";
        EXPECT_TRUE(stream.CR & DMA_SxCR_EN);
        EXPECT_TRUE(epuck2_model_dcmi.CR & DCMI_CR_CAPTURE);
        EXPECT_EQ(0u, (epuck2_model_dma2.LISR >> SHIFT) & DMA_FLAGS_ALL) << "the stream's flags cleared";
    }
};

TEST_F(Camera, I2cRunsFastModeAt400kHzOnPb8Pb9) {
    const stm32_i2c &i2c = epuck2_model_i2c1;
    EXPECT_EQ(42u, i2c.CR2 & 0x3F) << "APB1 at 42 MHz";
    EXPECT_TRUE(i2c.CCR & I2C_CCR_FS);
    EXPECT_EQ(42000000u / (3 * (i2c.CCR & 0xFFF)), 400000u) << "a bit is 3 CCR periods";
    EXPECT_EQ(13u, i2c.TRISE) << "300 ns at 42 MHz, + 1";
    EXPECT_TRUE(i2c.CR1 & I2C_CR1_PE);
    for (unsigned pin : {8u, 9u}) {
        EXPECT_EQ(GPIO_MODE_ALTERNATE, (epuck2_model_gpiob.MODER >> (2 * pin)) & 3u) << "PB" << pin;
        EXPECT_EQ(4u, (epuck2_model_gpiob.AFR[1] >> (4 * (pin - 8))) & 0xFu) << "PB" << pin << " AF4";
        EXPECT_TRUE(epuck2_model_gpiob.OTYPER & (1u << pin)) << "PB" << pin << " open drain";
    }
}

TEST_F(Camera, EachSensorWriteIsStartAddressRegisterValueStop) {
    ASSERT_TRUE(start());
    ASSERT_GT(bus->log.size(), 10u);
    EXPECT_TRUE(bus->log.front().clocked) << "the sensor's clock runs before it is written";
    for (const Transaction &t : bus->log) {
        ASSERT_EQ(3u, t.bytes.size());
        EXPECT_EQ(0xDC, t.bytes[0]) << "0x6E, write";
        EXPECT_TRUE(t.stopped);
    }
}

TEST_F(Camera, TheSensorIsSetToTheWholeViewAt160x120Rgb565) {
    ASSERT_TRUE(start());
    const unsigned A = 0, B = 1;
    EXPECT_EQ(0x30, bus->reg[B][0x4E]) << "RGB565";
    EXPECT_EQ(0x80, bus->reg[B][0x93]) << "x scaled 1/4";
    EXPECT_EQ(0x80, bus->reg[B][0x94]) << "y scaled 1/4";
    unsigned x1 = bus->pair(A, 0x08), y1 = bus->pair(A, 0x0A), x2 = bus->pair(A, 0x0C), y2 = bus->pair(A, 0x0E);
    EXPECT_EQ(W, x2 - x1 + 1) << "the window, in output pixels";
    EXPECT_EQ(H, y2 - y1 + 1);
    EXPECT_EQ(1u, x1);
    EXPECT_EQ(1u, y1);
    EXPECT_EQ(640u, (x2 - x1 + 1) * 4) << "the whole array's width";
    EXPECT_EQ(480u, (y2 - y1 + 1) * 4);
    EXPECT_EQ(x1, bus->pair(A, 0x35)) << "auto-exposure over the window";
    EXPECT_EQ(x2, bus->pair(A, 0x37));
    EXPECT_EQ(y1, bus->pair(A, 0x39));
    EXPECT_EQ(y2, bus->pair(A, 0x3B));
    unsigned cx1 = bus->pair(A, 0x3D), cx2 = bus->pair(A, 0x3F), cy1 = bus->pair(A, 0x41), cy2 = bus->pair(A, 0x43);
    EXPECT_TRUE(x1 < cx1 && cx1 < cx2 && cx2 < x2) << "the centre window inside";
    EXPECT_TRUE(y1 < cy1 && cy1 < cy2 && cy2 < y2);
}

TEST_F(Camera, TheSensorClockIs21MHzOnPa0) {
    ASSERT_TRUE(start());
    const stm32_timer &t = epuck2_model_tim5;
    EXPECT_EQ(21000000u, 84000000u / ((t.PSC + 1) * (t.ARR + 1)));
    EXPECT_EQ((t.ARR + 1) / 2, t.CCR[0]) << "half high";
    EXPECT_EQ(TIM_CCMR1_OC1M_PWM1, t.CCMR1 & (7u << 4));
    EXPECT_TRUE(t.CCER & TIM_CCER_CC1E);
    EXPECT_TRUE(t.CR1 & TIM_CR1_CEN);
    EXPECT_EQ(2u, epuck2_model_gpioa.AFR[0] & 0xFu) << "PA0 AF2: TIM5_CH1";
}

TEST_F(Camera, ASensorThatDoesNotAnswerFailsInitAndFreesTheBus) {
    bus->nack = true;
    EXPECT_FALSE(start());
    ASSERT_EQ(1u, bus->log.size()) << "the first write fails, no other is tried";
    EXPECT_EQ(std::vector<uint8_t>{0xDC}, bus->log[0].bytes);
    EXPECT_TRUE(bus->log[0].stopped) << "a STOP after the NACK";
    EXPECT_LT(epuck2_model_polls, 100u) << "the NACK ends the write at once, no timeout";
    EXPECT_FALSE(epuck2_model_dcmi.CR & DCMI_CR_ENABLE) << "no capture without a sensor";
}

TEST_F(Camera, AnI2cBlockThatNeverAnswersTimesOut) {
    bus->mute = true;
    EXPECT_FALSE(epuck2_i2c_write(0x6E, 0x03, 0x00));
    EXPECT_GT(epuck2_model_polls, 1000u) << "it waited";
    EXPECT_LT(epuck2_model_polls, 1000000u) << "but not forever";
    EXPECT_TRUE(epuck2_model_i2c1.CR1 & I2C_CR1_STOP) << "and asked for a STOP";
}

TEST_F(Camera, DcmiAndDmaAreSetForOneFrameOfWords) {
    ASSERT_TRUE(start());
    const stm32_dcmi &d = epuck2_model_dcmi;
    EXPECT_TRUE(d.CR & DCMI_CR_ENABLE);
    EXPECT_TRUE(d.CR & DCMI_CR_CAPTURE);
    EXPECT_TRUE(d.CR & DCMI_CR_CM_SNAPSHOT) << "one frame a capture";
    EXPECT_TRUE(d.CR & DCMI_CR_PCKPOL) << "sampled on PCLK's rising edge";
    EXPECT_EQ(0u, d.CR & (DCMI_CR_HSPOL | DCMI_CR_VSPOL | DCMI_CR_EDM_MASK)) << "syncs active low, 8 bits";
    EXPECT_EQ(DCMI_IT_FRAME | DCMI_IT_OVR | DCMI_IT_ERR, d.IER);
    EXPECT_EQ((uint32_t)(uintptr_t)&epuck2_model_dcmi.DR, stream.PAR);
    EXPECT_EQ((uint32_t)(uintptr_t)epuck2_camera_model_dma_memory(), stream.M0AR);
    EXPECT_EQ(W * H * 2 / 4, stream.NDTR) << "frame bytes / 4";
    EXPECT_EQ(1u, (stream.CR >> 25) & 7u) << "channel 1: the DCMI";
    EXPECT_EQ(0u, stream.CR & DMA_SxCR_DIR_MASK) << "peripheral to memory";
    EXPECT_EQ(DMA_SxCR_PSIZE_WORD | DMA_SxCR_MSIZE_WORD, stream.CR & (0xFu << 11));
    EXPECT_TRUE(stream.CR & DMA_SxCR_MINC);
    EXPECT_FALSE(stream.CR & DMA_SxCR_CIRC);
    EXPECT_TRUE(stream.CR & DMA_SxCR_TCIE);
    EXPECT_TRUE(stream.CR & DMA_SxCR_TEIE);
    EXPECT_TRUE(stream.CR & DMA_SxCR_EN);
    EXPECT_TRUE(stream.FCR & DMA_SxFCR_DMDIS);
    struct Pin {
        stm32_gpio *port;
        unsigned pin;
    };
    for (Pin p : {Pin{&epuck2_model_gpioa, 4}, Pin{&epuck2_model_gpioa, 6}, Pin{&epuck2_model_gpiob, 6},
                  Pin{&epuck2_model_gpiob, 7}, Pin{&epuck2_model_gpioc, 6}, Pin{&epuck2_model_gpioc, 7},
                  Pin{&epuck2_model_gpioe, 0}, Pin{&epuck2_model_gpioe, 1}, Pin{&epuck2_model_gpioe, 4},
                  Pin{&epuck2_model_gpioe, 5}, Pin{&epuck2_model_gpioe, 6}}) {
        EXPECT_EQ(GPIO_MODE_ALTERNATE, (p.port->MODER >> (2 * p.pin)) & 3u) << "pin " << p.pin;
        EXPECT_EQ(13u, (p.port->AFR[p.pin / 8] >> (4 * (p.pin % 8))) & 0xFu) << "pin " << p.pin;
    }
}

TEST_F(Camera, ATransferCompleteHandsOnTheFrameAsRgb565) {
    ASSERT_TRUE(start());
    sensor_sends_frame();
    uint8_t *m = epuck2_camera_model_dma_memory();
    m[0] = 0xF8, m[1] = 0x00; // pixel 0 pure red: RRRRRGGG GGGBBBBB
    transfer_complete();
    ASSERT_EQ(1u, frames.size());
    EXPECT_EQ(W, frames[0].width);
    EXPECT_EQ(H, frames[0].height);
    const std::vector<uint16_t> &px = frame_pixels[0];
    EXPECT_EQ(0xF800, px[0]) << "red, not 0x00F8 (blue and green)";
    for (unsigned i = 1; i < W * H; i++) ASSERT_EQ(v(i), px[i]) << "pixel " << i;
    EXPECT_EQ(0u, epuck2_camera_frames_dropped());
}

TEST_F(Camera, TheNextCaptureWaitsForTheHandOverAndTheFrameEnd) {
    ASSERT_TRUE(start());
    sensor_sends_frame();
    transfer_complete();
    EXPECT_FALSE(capturing()) << "the DCMI may still be in the frame";
    frame_end();
    expect_rearmed();
    // The other order: the frame end first, the DMA's FIFO still draining.
    sensor_sends_frame();
    epuck2_model_dcmi.CR &= ~DCMI_CR_CAPTURE;
    frame_end();
    EXPECT_EQ(0u, epuck2_model_dcmi.RIS) << "the flag cleared, or its interrupt would come back at once";
    EXPECT_FALSE(capturing()) << "the frame not yet handed on: its memory is in use";
    transfer_complete();
    EXPECT_EQ(2u, frames.size());
    expect_rearmed();
}

TEST_F(Camera, AFrameOnlyAtTransferComplete) {
    ASSERT_TRUE(start());
    sensor_sends_frame();
    dma_interrupt(DMA_FLAG_HT);
    dma_interrupt(0);
    EXPECT_EQ(0u, frames.size()) << "half a frame is no frame";
    transfer_complete();
    dma_interrupt(0);
    frame_end();
    EXPECT_EQ(1u, frames.size()) << "one frame a transfer";
    frame_end();
    EXPECT_EQ(1u, frames.size()) << "a frame end alone hands nothing on";
    whole_frame();
    EXPECT_EQ(2u, frames.size());
}

TEST_F(Camera, AnOverrunDropsTheFrameAndRestartsTheCapture) {
    ASSERT_TRUE(start());
    epuck2_model_dma2.S[1].NDTR = 1234; // part way
    dcmi_interrupt(DCMI_IT_OVR);
    EXPECT_EQ(0u, epuck2_model_dcmi.RIS) << "the overrun flag cleared";
    EXPECT_EQ(1u, epuck2_camera_frames_dropped());
    EXPECT_TRUE(epuck2_model_dcmi.CR & DCMI_CR_ENABLE);
    expect_rearmed();
    EXPECT_EQ(0u, frames.size());
    whole_frame();
    EXPECT_EQ(1u, frames.size()) << "the next frame is whole";
}

TEST_F(Camera, ATransferCompleteWithAnOverrunPendingIsNoFrame) {
    ASSERT_TRUE(start());
    sensor_sends_frame();
    epuck2_model_dcmi.RIS |= DCMI_IT_OVR;
    transfer_complete();
    EXPECT_EQ(0u, frames.size()) << "bytes are missing from it";
    EXPECT_EQ(1u, epuck2_camera_frames_dropped());
    expect_rearmed();
    epuck2_model_dcmi.RIS &= ~epuck2_model_dcmi.ICR; // the ICR write took it
    EXPECT_EQ(0u, epuck2_model_dcmi.RIS);
    whole_frame();
    EXPECT_EQ(1u, frames.size()) << "the next frame is whole";
}

TEST_F(Camera, ADmaErrorDropsTheFrame) {
    ASSERT_TRUE(start());
    epuck2_model_dma2.S[1].CR &= ~DMA_SxCR_EN; // an error stops the stream
    dma_interrupt(DMA_FLAG_TE);
    EXPECT_EQ(0u, frames.size());
    EXPECT_EQ(1u, epuck2_camera_frames_dropped());
    expect_rearmed();
}

}  // namespace
