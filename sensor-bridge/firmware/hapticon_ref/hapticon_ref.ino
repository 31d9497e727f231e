// Hapticon reference firmware: samples analog channels (flex sensors, FSRs) at a fixed rate and
// drives force-feedback servos, speaking the Hapticon framed protocol (docs/protocols.md) over USB
// serial. For Teensy 3.x/4.x, Arduino Leonardo/Micro, RP2040 and other Arduino-core boards.
//
// Bandwidth: a 5-channel sample frame is 20 bytes + COBS + delimiter = 22 bytes, so 1 kHz needs
// about 22 kB/s. Native-USB boards (Teensy, Leonardo, RP2040, ESP32-S2/S3) ignore the baud rate and
// manage easily; boards behind a USB-UART bridge (Uno, Nano, ESP32 DevKit) need HFP_BAUD of at
// least 460800 for 1 kHz (115200 carries about 500 Hz), and the host must open the port at the same
// rate. When the serial buffer is full a sample is skipped rather than blocking: the host sees a
// longer time step between frames, not a sequence gap.
//
// Compliance grains (grains.h) run on the board itself: channel HFP_GRAIN_CHANNEL is the force sensor,
// and each grain drives the 3x3 electrode array through ELECTRODE_PINS (one switch per electrode, the
// active electrode as anode against the common return) at the amplitude set on AMPLITUDE_PIN. The
// decision and the first pulse happen in the same loop() pass as the sample, so force to pulse takes
// one sample period plus the filter (well under 25 ms); the host sends calibrated levels and the
// condition (grains, distribution, electrodes) with SET_GRAINS, and each calibration stimulus (one
// electrode, 200 ms) with STIMULATE. Until it does, every step is 0 and no current flows.
//
// The protocol logic lives in hfp.*, hfp_device.* and grains.* (plain C++, tested on the host by
// ../test/run.sh); this file only binds it to the board.
#include <Servo.h>

#include "grains.h"
#include "hfp.h"
#include "hfp_device.h"

// ---- Configuration ---------------------------------------------------------------------------
#ifndef HFP_BAUD
#define HFP_BAUD 115200
#endif
#ifndef HFP_SAMPLE_RATE_HZ
#define HFP_SAMPLE_RATE_HZ 1000
#endif

static const uint8_t CHANNEL_PINS[] = {A0, A1, A2, A3, A4};  // thumb..pinky flex sensors
static const uint8_t CHANNEL_UNITS[] = {0, 0, 0, 0, 0};       // raw ADC counts
static const uint8_t SERVO_PINS[] = {2, 3, 4, 5, 6};          // thumb..pinky force feedback
static const uint8_t CHANNEL_COUNT = sizeof(CHANNEL_PINS);
static const uint8_t SERVO_COUNT = sizeof(SERVO_PINS);
static const uint8_t ADC_BITS = 10;  // analogRead's default resolution on every Arduino core
#ifndef HFP_GRAIN_CHANNEL
#define HFP_GRAIN_CHANNEL 0  // the force sensor's channel
#endif
static const uint8_t ELECTRODE_PINS[hgr::ELECTRODES] = {7, 8, 9, 10, 11, 12, 13, 20, 21};  // electrodes 0..8
static const uint8_t AMPLITUDE_PIN = 22;  // PWM/DAC setting the current source, 0..255 for steps 0..200

static const hfp::DeviceConfig CONFIG = {
    1, 0, 0,             // firmware version
    ADC_BITS,
    HFP_SAMPLE_RATE_HZ,  // initial rate
    4000,                // highest rate SET_SAMPLE_RATE accepts
    CHANNEL_COUNT,
    SERVO_COUNT,
    CHANNEL_UNITS,
    "hapticon-ref",
};

// ---- Hardware bindings -----------------------------------------------------------------------
class SerialSink : public hfp::ByteSink {
 public:
  void write(const uint8_t* bytes, size_t length) override { Serial.write(bytes, length); }
};

class ServoOutputs : public hfp::OutputDriver {
 public:
  void attach() {
    for (uint8_t i = 0; i < SERVO_COUNT; i++) {
      servos_[i].attach(SERVO_PINS[i]);
      setOutput(i, hfp::SERVO_MIN);
    }
  }
  // Travel 0..1000 maps onto the standard 1000..2000 us servo pulse. Out-of-range values never get
  // here: hfp::Device NACKs them, and this clamp is a last line of defence.
  void setOutput(uint8_t index, uint16_t travel) override {
    if (index >= SERVO_COUNT) return;
    if (travel > hfp::SERVO_MAX) travel = hfp::SERVO_MAX;
    servos_[index].writeMicroseconds(1000 + travel);
  }

 private:
  Servo servos_[SERVO_COUNT];
};

// One pulse at a time (time-division scanning): set the level, close the electrode's switch for 200 us.
// Blocking for 200 us is fine: the next electrode's slot starts 250 us after this one.
class ElectrodeArray : public hgr::Stimulator {
 public:
  void attach() {
    for (uint8_t e = 0; e < hgr::ELECTRODES; e++) {
      pinMode(ELECTRODE_PINS[e], OUTPUT);
      digitalWrite(ELECTRODE_PINS[e], LOW);
    }
    analogWrite(AMPLITUDE_PIN, 0);
  }
  void pulse(uint8_t electrode, uint8_t step, uint32_t) override {
    if (electrode >= hgr::ELECTRODES || step == 0) return;
    if (step > hgr::AMPLITUDE_STEPS) step = hgr::AMPLITUDE_STEPS;  // last line of defence for 2.7 mA
    analogWrite(AMPLITUDE_PIN, (int)((uint16_t)step * 255 / hgr::AMPLITUDE_STEPS));
    digitalWrite(ELECTRODE_PINS[electrode], HIGH);
    delayMicroseconds(hgr::PULSE_MICROS);
    digitalWrite(ELECTRODE_PINS[electrode], LOW);
    analogWrite(AMPLITUDE_PIN, 0);
  }
};

static SerialSink sink;
static ServoOutputs outputs;
static ElectrodeArray electrodes;
static hgr::GrainRenderer grains;
static hfp::Device device(CONFIG, sink, outputs, 0, &grains);

// ---- Sketch ----------------------------------------------------------------------------------
void setup() {
  Serial.begin(HFP_BAUD);
  outputs.attach();
  electrodes.attach();
  grains.configure(hgr::defaultParams(ADC_BITS), HFP_SAMPLE_RATE_HZ);
  device.begin();
}

void loop() {
  uint8_t incoming[64];
  int available = Serial.available();
  while (available > 0) {
    size_t n = 0;
    while (n < sizeof(incoming) && available > 0) {
      incoming[n++] = (uint8_t)Serial.read();
      available--;
    }
    device.receive(incoming, n);
  }

  uint32_t now = micros();
  if (device.sampleDue(now)) {
    uint16_t values[CHANNEL_COUNT];
    for (uint8_t c = 0; c < CHANNEL_COUNT; c++) values[c] = (uint16_t)analogRead(CHANNEL_PINS[c]);
    grains.offer(now, values[HFP_GRAIN_CHANNEL]);
    // Worst case for this frame: header 4 + timestamp 4 + 2 per channel + CRC 2, COBS +1, delimiter +1.
    if (Serial.availableForWrite() >= (int)(12 + 2 * CHANNEL_COUNT)) device.sendSample(now, values);
  }
  grains.service(micros(), electrodes);
}
