// The reference device's protocol logic, independent of the board: answers host commands (with the
// safety limits enforced), schedules and sends sample frames. The sketch supplies the hardware
// through ByteSink and OutputDriver; the host tests supply fakes.
#ifndef HAPTICON_HFP_DEVICE_H
#define HAPTICON_HFP_DEVICE_H

#include "grains.h"
#include "hfp.h"

namespace hfp {

// Where encoded frames go (the serial port).
class ByteSink {
 public:
  virtual void write(const uint8_t* bytes, size_t length) = 0;

 protected:
  ~ByteSink() {}
};

// The servo/PWM outputs. travel is already checked to be in SERVO_MIN..SERVO_MAX.
class OutputDriver {
 public:
  virtual void setOutput(uint8_t index, uint16_t travel) = 0;

 protected:
  ~OutputDriver() {}
};

struct DeviceConfig {
  uint8_t firmwareMajor;
  uint8_t firmwareMinor;
  uint8_t firmwarePatch;
  uint8_t adcBits;
  uint32_t sampleRateHz;     // initial rate
  uint32_t maxSampleRateHz;  // SET_SAMPLE_RATE above this is NACKed
  uint8_t channelCount;      // 1..MAX_CHANNELS
  uint8_t outputCount;       // 0..MAX_OUTPUTS
  const uint8_t* units;      // channelCount unit codes (0 raw, 1 mV, 2 g, 3 mN, 4 centidegrees)
  const char* name;          // printable ASCII, at most MAX_NAME characters
};

class Device {
 public:
  // grains, when given, renders compliance grains stand-alone and takes SET_GRAINS updates and STIMULATE
  // calibration stimuli; without it both are NACKed as unknown.
  Device(const DeviceConfig& config, ByteSink& sink, OutputDriver& outputs, uint16_t firstSequence = 0,
         hgr::GrainRenderer* grains = 0);

  // Flushes the line with a lone delimiter and announces the device with a device-info frame.
  void begin();
  // Handles bytes from the host; answers each complete command.
  void receive(const uint8_t* bytes, size_t length);
  // True when a sample is due at nowMicros (micros(), wrap-safe). After a stall longer than one
  // period the schedule restarts from now instead of sending a burst.
  bool sampleDue(uint32_t nowMicros);
  // Sends one sample frame with config.channelCount values.
  void sendSample(uint32_t timestampMicros, const uint16_t* values);
  void sendDeviceInfo();

  uint16_t output(uint8_t index) const { return index < MAX_OUTPUTS ? outputs_[index] : 0; }
  uint32_t sampleRateHz() const { return sampleRateHz_; }
  const FrameDecoder& decoder() const { return decoder_; }

 private:
  void handle(const Frame& frame);
  void setOutputs(const Frame& frame);
  void setSampleRate(const Frame& frame);
  void setGrains(const Frame& frame);
  void stimulate(const Frame& frame);
  void ack(uint16_t sequence, uint8_t status, uint8_t detail);
  void send();

  const DeviceConfig& config_;
  ByteSink& sink_;
  OutputDriver& driver_;
  hgr::GrainRenderer* grains_;
  FrameWriter writer_;
  FrameDecoder decoder_;
  uint16_t outputs_[MAX_OUTPUTS];
  uint8_t encoded_[MAX_ENCODED];
  uint32_t sampleRateHz_;
  uint32_t periodMicros_;
  uint32_t nextDue_;
  bool scheduled_;
};

}  // namespace hfp

#endif
