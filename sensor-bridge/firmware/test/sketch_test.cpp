// Runs hapticon_ref.ino on the host against stubbed hardware: boot, 10 ms of sampling at 1 kHz, a
// force-feedback command. Checks what the sketch sends and what it does to the servos.
#include <stdio.h>
#include <string.h>

#include "Arduino.h"
#include "hfp.h"

void setup();
void loop();

StubSerial Serial;
static uint32_t now = 0;
uint32_t micros() { return now; }
int analogRead(uint8_t pin) { return (int)(pin - A0) * 100 + (int)(now / 1000); }

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
  printf("sketch_test: %d infos, %d samples, %d acks, %d failed\n", infos, samples, acks, failures);
  return failures == 0 ? 0 : 1;
}
