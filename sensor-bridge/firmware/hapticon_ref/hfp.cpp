#include "hfp.h"

namespace hfp {

uint16_t crc16(const uint8_t* data, size_t length, uint16_t crc) {
  // Bitwise rather than a 512-byte table: an Uno has 2 KB of RAM, and 1 kHz frames of ~20 bytes
  // cost well under 1 % of a 16 MHz CPU this way.
  for (size_t i = 0; i < length; i++) {
    crc ^= (uint16_t)data[i] << 8;
    for (uint8_t bit = 0; bit < 8; bit++) crc = (crc & 0x8000) ? (uint16_t)((crc << 1) ^ 0x1021) : (uint16_t)(crc << 1);
  }
  return crc;
}

size_t cobsEncode(const uint8_t* source, size_t length, uint8_t* destination) {
  size_t codeAt = 0;
  size_t out = 1;
  uint8_t code = 1;
  for (size_t i = 0; i < length; i++) {
    if (source[i] == 0) {
      destination[codeAt] = code;
      codeAt = out++;
      code = 1;
    } else {
      destination[out++] = source[i];
      code++;
      // A full block ends here; the canonical encoding starts the next only if data follows.
      if (code == 0xFF && i + 1 < length) {
        destination[codeAt] = code;
        codeAt = out++;
        code = 1;
      }
    }
  }
  destination[codeAt] = code;
  return out;
}

void FrameWriter::begin(uint8_t type, uint8_t version) {
  length_ = 0;
  frame_[length_++] = version;
  frame_[length_++] = type;
  frame_[length_++] = (uint8_t)(sequence_ & 0xFF);
  frame_[length_++] = (uint8_t)(sequence_ >> 8);
}

void FrameWriter::u8(uint8_t value) {
  if (length_ < MAX_FRAME - CRC_LENGTH) frame_[length_++] = value;
}

void FrameWriter::u16(uint16_t value) {
  u8((uint8_t)(value & 0xFF));
  u8((uint8_t)(value >> 8));
}

void FrameWriter::u32(uint32_t value) {
  u16((uint16_t)(value & 0xFFFF));
  u16((uint16_t)(value >> 16));
}

size_t FrameWriter::end(uint8_t* out) {
  uint16_t crc = crc16(frame_, length_);
  frame_[length_++] = (uint8_t)(crc >> 8);
  frame_[length_++] = (uint8_t)(crc & 0xFF);
  size_t n = cobsEncode(frame_, length_, out);
  out[n++] = 0;
  sequence_++;
  return n;
}

void FrameDecoder::reset() {
  length_ = 0;
  code_ = 0;
  remaining_ = 0;
  encoded_ = 0;
  overlong_ = false;
}

FrameDecoder::Result FrameDecoder::bad() {
  badFrames_++;
  droppedBytes_ += encoded_ + 1;
  reset();
  return BAD_FRAME;
}

FrameDecoder::Result FrameDecoder::feed(uint8_t b) {
  if (b != 0) {
    encoded_++;
    if (overlong_) return NOTHING;
    if (remaining_ == 0) {
      // A block shorter than 254 data bytes stands for a zero, unless the frame ends here.
      if (code_ != 0 && code_ != 0xFF) {
        if (length_ == MAX_FRAME) overlong_ = true; else buffer_[length_++] = 0;
      }
      code_ = b;
      remaining_ = (uint8_t)(b - 1);
    } else {
      if (length_ == MAX_FRAME) overlong_ = true; else buffer_[length_++] = b;
      remaining_--;
    }
    return NOTHING;
  }
  if (encoded_ == 0) {  // An idle delimiter.
    droppedBytes_++;
    return NOTHING;
  }
  if (overlong_ || remaining_ != 0 || length_ < HEADER_LENGTH + CRC_LENGTH || crc16(buffer_, length_) != 0) return bad();
  frame_.version = buffer_[0];
  frame_.type = buffer_[1];
  frame_.sequence = readU16(buffer_ + 2);
  frame_.payload = buffer_ + HEADER_LENGTH;
  frame_.payloadLength = length_ - HEADER_LENGTH - CRC_LENGTH;
  frames_++;
  reset();
  return FRAME;
}

}  // namespace hfp
