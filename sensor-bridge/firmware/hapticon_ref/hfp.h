// Hapticon framed protocol, version 1: the portable part shared by the firmware and its host tests.
// Frame layout, CRC and COBS are specified in docs/protocols.md; the Kotlin twin is
// org.hapticon.sensor.protocol.framed. No heap, no STL, no Arduino API: builds with avr-gcc and g++.
#ifndef HAPTICON_HFP_H
#define HAPTICON_HFP_H

#include <stddef.h>
#include <stdint.h>

namespace hfp {

const uint8_t VERSION = 1;

// Frame types. Device to host:
const uint8_t TYPE_DEVICE_INFO = 0x01;
const uint8_t TYPE_SAMPLE = 0x02;
const uint8_t TYPE_ACK = 0x03;
// Host to device:
const uint8_t TYPE_SET_OUTPUTS = 0x10;
const uint8_t TYPE_REQUEST_INFO = 0x11;
const uint8_t TYPE_SET_SAMPLE_RATE = 0x12;
const uint8_t TYPE_SET_GRAINS = 0x13;  // compliance-grain parameters (grains.h), 21-byte payload
const uint8_t TYPE_STIMULATE = 0x14;   // one calibration stimulus on one electrode (grains.h), 4-byte payload

// Acknowledgement status: ACK_OK accepts a command, the others reject it (NACK) and say why.
const uint8_t ACK_OK = 0;
const uint8_t NACK_OUT_OF_RANGE = 1;
const uint8_t NACK_BAD_OUTPUT = 2;
const uint8_t NACK_MALFORMED = 3;
const uint8_t NACK_UNKNOWN_COMMAND = 4;
const uint8_t NACK_UNSUPPORTED_VERSION = 5;

const size_t HEADER_LENGTH = 4;  // version, type, sequence (u16 little-endian)
const size_t CRC_LENGTH = 2;     // CRC-16/CCITT-FALSE, high byte first
const size_t MAX_PAYLOAD = 128;
const size_t MAX_FRAME = HEADER_LENGTH + MAX_PAYLOAD + CRC_LENGTH;
const size_t MAX_ENCODED = MAX_FRAME + (MAX_FRAME + 253) / 254 + 1;  // COBS overhead + delimiter
const uint8_t MAX_CHANNELS = 32;
const uint8_t MAX_OUTPUTS = 16;
const uint8_t MAX_NAME = 32;

// Servo command range, the same hard limit as the host's SafetyLimits.SERVO_MIN..SERVO_MAX.
const uint16_t SERVO_MIN = 0;
const uint16_t SERVO_MAX = 1000;

// CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection, no final XOR; "123456789" -> 0x29B1.
uint16_t crc16(const uint8_t* data, size_t length, uint16_t crc = 0xFFFF);

// COBS-encodes length bytes (canonical form, no delimiter); returns bytes written, at most
// length + length / 254 + 1.
size_t cobsEncode(const uint8_t* source, size_t length, uint8_t* destination);

// Builds frames and writes them COBS-encoded with their delimiter. Numbers frames with its own
// 16-bit sequence counter.
class FrameWriter {
 public:
  explicit FrameWriter(uint16_t firstSequence = 0) : length_(0), sequence_(firstSequence) {}
  void begin(uint8_t type) { begin(type, VERSION); }
  void begin(uint8_t type, uint8_t version);
  // Appenders; bytes beyond MAX_FRAME - CRC_LENGTH are ignored (callers stay within MAX_PAYLOAD).
  void u8(uint8_t value);
  void u16(uint16_t value);
  void u32(uint32_t value);
  // Appends the CRC, encodes into out (at least MAX_ENCODED bytes) with the 0x00 delimiter, advances
  // the sequence number and returns the bytes written.
  size_t end(uint8_t* out);
  uint16_t nextSequence() const { return sequence_; }

 private:
  uint8_t frame_[MAX_FRAME];
  size_t length_;
  uint16_t sequence_;
};

// A decoded frame with a good CRC. payload points into the decoder and is valid until the next feed.
struct Frame {
  uint8_t version;
  uint8_t type;
  uint16_t sequence;
  const uint8_t* payload;
  size_t payloadLength;
};

// Incremental COBS + CRC decoder: bytes in one at a time, frames out. Resynchronises on every 0x00.
class FrameDecoder {
 public:
  enum Result { NOTHING, FRAME, BAD_FRAME };
  FrameDecoder() : length_(0), code_(0), remaining_(0), encoded_(0), overlong_(false),
                   frames_(0), badFrames_(0), droppedBytes_(0) {}
  // Returns FRAME when b completes a frame with a good CRC (then read frame()), BAD_FRAME when it
  // completes a broken one (bad COBS, too short, too long, CRC), NOTHING otherwise.
  Result feed(uint8_t b);
  const Frame& frame() const { return frame_; }
  uint32_t frames() const { return frames_; }
  uint32_t badFrames() const { return badFrames_; }
  uint32_t droppedBytes() const { return droppedBytes_; }

 private:
  void reset();
  Result bad();
  uint8_t buffer_[MAX_FRAME];
  size_t length_;
  uint8_t code_;
  uint8_t remaining_;
  size_t encoded_;
  bool overlong_;
  Frame frame_;
  uint32_t frames_;
  uint32_t badFrames_;
  uint32_t droppedBytes_;
};

// Little-endian readers for payload fields.
inline uint16_t readU16(const uint8_t* p) { return (uint16_t)(p[0] | ((uint16_t)p[1] << 8)); }
inline uint32_t readU32(const uint8_t* p) { return (uint32_t)readU16(p) | ((uint32_t)readU16(p + 2) << 16); }

}  // namespace hfp

#endif
