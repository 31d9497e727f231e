// Runs hapticon_ref.ino on the host against stubbed hardware: boot, 10 ms of sampling at 1 kHz, a
// force-feedback command. Checks what the sketch sends and what it does to the servos.
#include <stdio.h>
#include <string.h>

#include "Arduino.h"
#include "grains.h"
#include "hfp.h"

void setup();
void loop();

StubSerial Serial;
static uint32_t now = 0;
uint32_t micros() { return now; }
static int forceA0 = -1;  // when >= 0, what A0 (the grain force channel) reads
int analogRead(uint8_t pin) {
  if (pin == A0 && forceA0 >= 0) return forceA0;
  return (int)(pin - A0) * 100 + (int)(now / 1000);
}
int pinLevel[64];
int electrodePulses[64];
int lastAmplitude = -1;
int maxAmplitude = 0;
void pinMode(uint8_t, uint8_t) {}
void digitalWrite(uint8_t pin, uint8_t level) {
  if (level == HIGH && pinLevel[pin] == LOW) electrodePulses[pin]++;
  pinLevel[pin] = level;
}
void analogWrite(uint8_t, int value) {
  lastAmplitude = value;
  if (value > maxAmplitude) maxAmplitude = value;
}
void delayMicroseconds(unsigned int us) { now += us; }

int servoPulseByPin[64];

static int failures = 0;
#define CHECK(condition)                                                                 \
  do {                                                                                   \
    if (!(condition)) {                                                                  \
      failures++;                                                                        \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #condition);      \
    }                                                                                    \
  } while (0)

int main() {
  setup();
  CHECK(Serial.baud == 115200);
  for (int pin = 2; pin <= 6; pin++) CHECK(servoPulseByPin[pin] == 1000);  // attached at travel 0
  // 10.05 ms of loop() calls, one every 50 us.
  for (now = 0; now <= 10050; now += 50) loop();

  // A host command: outputs 0..4 = 0, 250, 500, 750, 1000, sequence 10 (the shared vector
  // "set-outputs-all").
  const uint8_t command[] = {0x04, 0x01, 0x10, 0x0a, 0x01, 0x01, 0x01, 0x02, 0xfa, 0x09, 0xf4, 0x01,
                             0xee, 0x02, 0xe8, 0x03, 0xa7, 0x41, 0x00};
  Serial.rx.insert(Serial.rx.end(), command, command + sizeof(command));
  loop();

  hfp::FrameDecoder decoder;
  int infos = 0, samples = 0, acks = 0;
  uint32_t lastTimestamp = 0;
  uint16_t expectedSequence = 0;
  for (size_t i = 0; i < Serial.tx.size(); i++) {
    if (decoder.feed(Serial.tx[i]) != hfp::FrameDecoder::FRAME) continue;
    const hfp::Frame& f = decoder.frame();
    CHECK(f.version == hfp::VERSION);
    CHECK(f.sequence == expectedSequence);
    expectedSequence++;
    if (f.type == hfp::TYPE_DEVICE_INFO) {
      infos++;
      CHECK(f.payload[8] == 5);  // channels
      CHECK(f.payload[9] == 5);  // outputs
      CHECK(hfp::readU32(f.payload + 4) == 1000);
    } else if (f.type == hfp::TYPE_SAMPLE) {
      CHECK(f.payloadLength == 4 + 2 * 5);
      uint32_t t = hfp::readU32(f.payload);
      CHECK(t == (uint32_t)samples * 1000);
      CHECK(hfp::readU16(f.payload + 4 + 2 * 3) == 300 + t / 1000);  // channel 3 = A3
      lastTimestamp = t;
      samples++;
    } else if (f.type == hfp::TYPE_ACK) {
      acks++;
      CHECK(hfp::readU16(f.payload) == 10);
      CHECK(f.payload[2] == hfp::ACK_OK);
    }
  }
  CHECK(Serial.tx.size() > 0 && Serial.tx[0] == 0);  // the flush delimiter
  CHECK(infos == 1);
  CHECK(samples == 11);  // at 0, 1000, ..., 10000 us
  CHECK(lastTimestamp == 10000);
  CHECK(acks == 1);
  CHECK(decoder.badFrames() == 0);
  // Servos on pins 2..6 (thumb..pinky): travel 0..1000 as 1000..2000 us pulses.
  const int pulses[] = {1000, 1250, 1500, 1750, 2000};
  for (int i = 0; i < 5; i++) CHECK(servoPulseByPin[2 + i] == pulses[i]);
  // No grain without a calibrated level: every step is 0 until SET_GRAINS.
  for (int pin = 0; pin < 64; pin++) CHECK(electrodePulses[pin] == 0);

  // SET_GRAINS: 9 grains over 0..1000, linear, the small square (electrodes 0, 1, 3, 4) at step 200
  // (2.7 mA), 20 Hz, a 9 ms dead time (the grain's own delivery on 4 electrodes), sequence 11. Then a 20 s slow
  // press on A0.
  uint8_t payload[21] = {9, 0, 0x00, 0x00, 0xe8, 0x03, 0x1b, 0x00, 200, 200, 0, 200, 200, 0, 0, 0, 0, 0xc8, 0x00, 0x28, 0x23};
  hfp::FrameWriter writer(11);
  writer.begin(hfp::TYPE_SET_GRAINS);
  for (size_t i = 0; i < sizeof(payload); i++) writer.u8(payload[i]);
  uint8_t encoded[hfp::MAX_ENCODED];
  size_t n = writer.end(encoded);
  Serial.tx.clear();
  Serial.rx.insert(Serial.rx.end(), encoded, encoded + n);
  forceA0 = 0;
  uint32_t start = now;
  for (uint32_t k = 0; k < 21000; k++) {
    forceA0 = k < 20000 ? (int)(k / 20) : 1000;
    uint32_t end = start + (k + 1) * 1000;
    while (now < end) {
      loop();
      now += 50;
    }
  }
  hfp::FrameDecoder replies;
  int grainAcks = 0;
  for (size_t i = 0; i < Serial.tx.size(); i++) {
    if (replies.feed(Serial.tx[i]) == hfp::FrameDecoder::FRAME && replies.frame().type == hfp::TYPE_ACK) {
      CHECK(hfp::readU16(replies.frame().payload) == 11);
      CHECK(replies.frame().payload[2] == hfp::ACK_OK);
      grainAcks++;
    }
  }
  CHECK(grainAcks == 1);
  // 9 grains x 2 pulses on each of the four electrodes (pins 7, 8, 10, 11), none elsewhere.
  const int electrodePins[] = {7, 8, 9, 10, 11, 12, 13, 20, 21};
  const int expected[] = {18, 18, 0, 18, 18, 0, 0, 0, 0};
  for (int e = 0; e < 9; e++) CHECK(electrodePulses[electrodePins[e]] == expected[e]);
  CHECK(maxAmplitude == 255);  // step 200 = full scale = 2.7 mA
  CHECK(lastAmplitude == 0);
  int grainPulses = electrodePulses[7] + electrodePulses[8] + electrodePulses[10] + electrodePulses[11];

  // STIMULATE, sequence 12: electrode 2 (pin 9) alone at step 60 (0.81 mA) for 200 ms, as one calibration
  // stimulus; then sequence 13 asks for step 201, one past the 2.7 mA cap, and is refused with nothing driven.
  const uint8_t stimuli[2][4] = {{2, 60, 0xc8, 0x00}, {2, 201, 0xc8, 0x00}};
  Serial.tx.clear();
  for (int c = 0; c < 2; c++) {
    writer.begin(hfp::TYPE_STIMULATE);
    for (int i = 0; i < 4; i++) writer.u8(stimuli[c][i]);
    n = writer.end(encoded);
    Serial.rx.insert(Serial.rx.end(), encoded, encoded + n);
  }
  maxAmplitude = 0;
  for (uint32_t end = now + 300000; now < end; now += 50) loop();
  CHECK(electrodePulses[9] == 25);  // 200 ms at 125 Hz
  for (int e = 0; e < 9; e++) CHECK(e == 2 || electrodePulses[electrodePins[e]] == expected[e]);
  CHECK(maxAmplitude == 60 * 255 / 200);
  hfp::FrameDecoder stimulusReplies;
  int stimulusAcks = 0;
  for (size_t i = 0; i < Serial.tx.size(); i++) {
    if (stimulusReplies.feed(Serial.tx[i]) == hfp::FrameDecoder::FRAME && stimulusReplies.frame().type == hfp::TYPE_ACK) {
      const uint8_t* a = stimulusReplies.frame().payload;
      if (hfp::readU16(a) == 12) CHECK(a[2] == hfp::ACK_OK);
      if (hfp::readU16(a) == 13) CHECK(a[2] == hfp::NACK_OUT_OF_RANGE && a[3] == hgr::STEP_ABOVE_CAP);
      stimulusAcks++;
    }
  }
  CHECK(stimulusAcks == 2);
  printf("sketch_test: %d infos, %d samples, %d acks, %d grain pulses, %d stimulus pulses, %d failed\n", infos, samples,
         acks, grainPulses, electrodePulses[9], failures);
  return failures == 0 ? 0 : 1;
}
