#include "hfp_device.h"

#include <string.h>

namespace hfp {

Device::Device(const DeviceConfig& config, ByteSink& sink, OutputDriver& outputs, uint16_t firstSequence,
               hgr::GrainRenderer* grains)
    : config_(config), sink_(sink), driver_(outputs), grains_(grains), writer_(firstSequence),
      sampleRateHz_(config.sampleRateHz), periodMicros_(1000000UL / config.sampleRateHz), nextDue_(0), scheduled_(false) {
  for (uint8_t i = 0; i < MAX_OUTPUTS; i++) outputs_[i] = 0;
}

void Device::begin() {
  uint8_t delimiter = 0;
  sink_.write(&delimiter, 1);
  sendDeviceInfo();
}

void Device::receive(const uint8_t* bytes, size_t length) {
  for (size_t i = 0; i < length; i++) {
    if (decoder_.feed(bytes[i]) == FrameDecoder::FRAME) handle(decoder_.frame());
  }
}

void Device::handle(const Frame& frame) {
  // Frames with a bad CRC were dropped by the decoder: their sequence number cannot be trusted, so
  // they get no answer and the host's ack timeout covers them.
  if (frame.version != VERSION) return ack(frame.sequence, NACK_UNSUPPORTED_VERSION, frame.version);
  switch (frame.type) {
    case TYPE_SET_OUTPUTS:
      return setOutputs(frame);
    case TYPE_SET_SAMPLE_RATE:
      return setSampleRate(frame);
    case TYPE_SET_GRAINS:
      if (grains_ == 0) return ack(frame.sequence, NACK_UNKNOWN_COMMAND, frame.type);
      return setGrains(frame);
    case TYPE_STIMULATE:
      if (grains_ == 0) return ack(frame.sequence, NACK_UNKNOWN_COMMAND, frame.type);
      return stimulate(frame);
    case TYPE_REQUEST_INFO:
      if (frame.payloadLength != 0) return ack(frame.sequence, NACK_MALFORMED, 0);
      return sendDeviceInfo();
    default:
      return ack(frame.sequence, NACK_UNKNOWN_COMMAND, frame.type);
  }
}

void Device::setOutputs(const Frame& frame) {
  // payload: first output (u8), then one u16 per output (unsigned, so SERVO_MIN = 0 holds by type).
  // All values are checked before any is applied, so a rejected command changes nothing.
  if (frame.payloadLength < 3 || (frame.payloadLength - 1) % 2 != 0) return ack(frame.sequence, NACK_MALFORMED, 0);
  uint8_t first = frame.payload[0];
  size_t count = (frame.payloadLength - 1) / 2;
  if ((size_t)first + count > config_.outputCount) {
    return ack(frame.sequence, NACK_BAD_OUTPUT, first >= config_.outputCount ? first : config_.outputCount);
  }
  for (size_t i = 0; i < count; i++) {
    uint16_t travel = readU16(frame.payload + 1 + 2 * i);
    if (travel > SERVO_MAX) return ack(frame.sequence, NACK_OUT_OF_RANGE, (uint8_t)(first + i));
  }
  for (size_t i = 0; i < count; i++) {
    uint8_t index = (uint8_t)(first + i);
    outputs_[index] = readU16(frame.payload + 1 + 2 * i);
    driver_.setOutput(index, outputs_[index]);
  }
  ack(frame.sequence, ACK_OK, 0);
}

void Device::setSampleRate(const Frame& frame) {
  if (frame.payloadLength != 4) return ack(frame.sequence, NACK_MALFORMED, 0);
  uint32_t rate = readU32(frame.payload);
  if (rate < 1 || rate > config_.maxSampleRateHz) return ack(frame.sequence, NACK_OUT_OF_RANGE, 0);
  // The grain filter's cutoff must stay below the new Nyquist rate.
  if (grains_ != 0 && hgr::validate(grains_->params(), rate) != hgr::PARAMS_OK) return ack(frame.sequence, NACK_OUT_OF_RANGE, 0);
  if (grains_ != 0) grains_->configure(grains_->params(), rate);
  sampleRateHz_ = rate;
  periodMicros_ = 1000000UL / rate;
  scheduled_ = false;
  ack(frame.sequence, ACK_OK, 0);
}

void Device::setGrains(const Frame& frame) {
  // Checked whole before anything changes: a refused update leaves the running grains as they were.
  hgr::GrainParams params;
  if (!hgr::parseParams(frame.payload, frame.payloadLength, params)) return ack(frame.sequence, NACK_MALFORMED, 0);
  hgr::ParamError error = hgr::validate(params, sampleRateHz_);
  if (error != hgr::PARAMS_OK) return ack(frame.sequence, NACK_OUT_OF_RANGE, (uint8_t)error);
  grains_->configure(params, sampleRateHz_);
  ack(frame.sequence, ACK_OK, 0);
}

void Device::stimulate(const Frame& frame) {
  hgr::Stimulus stimulus;
  if (!hgr::parseStimulus(frame.payload, frame.payloadLength, stimulus)) return ack(frame.sequence, NACK_MALFORMED, 0);
  hgr::ParamError error = hgr::validate(stimulus);
  if (error != hgr::PARAMS_OK) return ack(frame.sequence, NACK_OUT_OF_RANGE, (uint8_t)error);
  grains_->stimulate(stimulus);
  ack(frame.sequence, ACK_OK, 0);
}

bool Device::sampleDue(uint32_t nowMicros) {
  if (!scheduled_) {
    scheduled_ = true;
    nextDue_ = nowMicros + periodMicros_;
    return true;
  }
  int32_t late = (int32_t)(nowMicros - nextDue_);
  if (late < 0) return false;
  // Keep the grid while on time; after a stall, restart from now rather than catching up.
  nextDue_ = (uint32_t)late >= periodMicros_ ? nowMicros + periodMicros_ : nextDue_ + periodMicros_;
  return true;
}

void Device::sendSample(uint32_t timestampMicros, const uint16_t* values) {
  writer_.begin(TYPE_SAMPLE);
  writer_.u32(timestampMicros);
  for (uint8_t c = 0; c < config_.channelCount; c++) writer_.u16(values[c]);
  send();
}

void Device::sendDeviceInfo() {
  writer_.begin(TYPE_DEVICE_INFO);
  writer_.u8(config_.firmwareMajor);
  writer_.u8(config_.firmwareMinor);
  writer_.u8(config_.firmwarePatch);
  writer_.u8(config_.adcBits);
  writer_.u32(sampleRateHz_);
  writer_.u8(config_.channelCount);
  writer_.u8(config_.outputCount);
  for (uint8_t c = 0; c < config_.channelCount; c++) writer_.u8(config_.units[c]);
  size_t nameLength = strlen(config_.name);
  if (nameLength > MAX_NAME) nameLength = MAX_NAME;
  for (size_t i = 0; i < nameLength; i++) writer_.u8((uint8_t)config_.name[i]);
  send();
}

void Device::ack(uint16_t sequence, uint8_t status, uint8_t detail) {
  writer_.begin(TYPE_ACK);
  writer_.u16(sequence);
  writer_.u8(status);
  writer_.u8(detail);
  send();
}

void Device::send() {
  size_t n = writer_.end(encoded_);
  sink_.write(encoded_, n);
}

}  // namespace hfp
