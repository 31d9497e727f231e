// The Servo library's interface as the sketch uses it; every pulse written is recorded by pin.
#ifndef HAPTICON_SERVO_STUB_H
#define HAPTICON_SERVO_STUB_H

extern int servoPulseByPin[64];

class Servo {
 public:
  Servo() : pin_(-1) {}
  void attach(int pin) { pin_ = pin; }
  void writeMicroseconds(int us) {
    if (pin_ >= 0 && pin_ < 64) servoPulseByPin[pin_] = us;
  }

 private:
  int pin_;
};

#endif
