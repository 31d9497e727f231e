// Just enough of the Arduino API to build hapticon_ref.ino on the host (see sketch_test.cpp).
#ifndef HAPTICON_ARDUINO_STUB_H
#define HAPTICON_ARDUINO_STUB_H

#include <stddef.h>
#include <stdint.h>

#include <deque>
#include <vector>

const uint8_t A0 = 14, A1 = 15, A2 = 16, A3 = 17, A4 = 18;

const uint8_t OUTPUT = 1, LOW = 0, HIGH = 1;

uint32_t micros();
int analogRead(uint8_t pin);
void pinMode(uint8_t pin, uint8_t mode);
void digitalWrite(uint8_t pin, uint8_t level);
void analogWrite(uint8_t pin, int value);
void delayMicroseconds(unsigned int us);

class StubSerial {
 public:
  StubSerial() : baud(0) {}
  void begin(unsigned long rate) { baud = rate; }
  int available() { return (int)rx.size(); }
  int read() {
    if (rx.empty()) return -1;
    int b = rx.front();
    rx.pop_front();
    return b;
  }
  size_t write(const uint8_t* bytes, size_t length) {
    tx.insert(tx.end(), bytes, bytes + length);
    return length;
  }
  int availableForWrite() { return 64; }

  unsigned long baud;
  std::deque<uint8_t> rx;  // bytes from the host, for the sketch to read
  std::vector<uint8_t> tx;  // bytes the sketch sent
};

extern StubSerial Serial;

#endif
