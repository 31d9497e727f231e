// Host tests of the firmware's protocol code (hfp.*, hfp_device.*), including the shared vectors that
// the Kotlin decoder and encoder are tested against too. Usage: host_test <framed-vectors.txt>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hfp.h"
#include "hfp_device.h"

namespace {

int checks = 0;
int failures = 0;

#include "check.h"

typedef std::vector<uint8_t> Bytes;

std::string hex(const Bytes& bytes) {
  static const char digits[] = "0123456789abcdef";
  std::string s;
  for (size_t i = 0; i < bytes.size(); i++) {
    s += digits[bytes[i] >> 4];
    s += digits[bytes[i] & 0xF];
  }
  return s;
}

Bytes unhex(const std::string& s) {
  Bytes bytes;
  if (s == "-") return bytes;
  for (size_t i = 0; i + 1 < s.size(); i += 2) bytes.push_back((uint8_t)strtoul(s.substr(i, 2).c_str(), NULL, 16));
  return bytes;
}

void checkBytes(const char* what, const std::string& name, const Bytes& actual, const Bytes& expected) {
  checks++;
  if (actual != expected) {
    failures++;
    fprintf(stderr, "%s %s:\n  expected %s\n  actual   %s\n", what, name.c_str(), hex(expected).c_str(), hex(actual).c_str());
  }
}

Bytes asBytes(const char* s) { return Bytes(s, s + strlen(s)); }

std::vector<unsigned long> numbers(const std::string& commaSeparated) {
  std::vector<unsigned long> values;
  std::stringstream in(commaSeparated);
  std::string item;
  while (std::getline(in, item, ',')) values.push_back(strtoul(item.c_str(), NULL, 10));
  return values;
}

class CaptureSink : public hfp::ByteSink {
 public:
  void write(const uint8_t* bytes, size_t length) { data.insert(data.end(), bytes, bytes + length); }
  Bytes data;
};

class RecordingOutputs : public hfp::OutputDriver {
 public:
  RecordingOutputs() : calls(0) { memset(values, 0, sizeof(values)); }
  void setOutput(uint8_t index, uint16_t travel) {
    values[index] = travel;
    calls++;
  }
  uint16_t values[hfp::MAX_OUTPUTS];
  int calls;
};

Bytes encode(hfp::FrameWriter& writer) {
  uint8_t out[hfp::MAX_ENCODED];
  size_t n = writer.end(out);
  return Bytes(out, out + n);
}

// Decodes a whole byte string; returns the good frames' types and counts the rest.
struct Decoded {
  std::vector<hfp::Frame> frames;
  std::vector<Bytes> payloads;
  int bad;
};

Decoded decodeAll(const Bytes& bytes, hfp::FrameDecoder& decoder) {
  Decoded d;
  d.bad = 0;
  for (size_t i = 0; i < bytes.size(); i++) {
    hfp::FrameDecoder::Result r = decoder.feed(bytes[i]);
    if (r == hfp::FrameDecoder::FRAME) {
      d.frames.push_back(decoder.frame());
      d.payloads.push_back(Bytes(decoder.frame().payload, decoder.frame().payload + decoder.frame().payloadLength));
    } else if (r == hfp::FrameDecoder::BAD_FRAME) {
      d.bad++;
    }
  }
  return d;
}

// ---- CRC and COBS ------------------------------------------------------------------------------

void crc16_checkValue_is29B1() {
  Bytes data = asBytes("123456789");
  CHECK(hfp::crc16(&data[0], data.size()) == 0x29B1);
  CHECK(hfp::crc16(NULL, 0) == 0xFFFF);
  // Appending the CRC high byte first makes the CRC of the whole 0.
  data.push_back(0x29);
  data.push_back(0xB1);
  CHECK(hfp::crc16(&data[0], data.size()) == 0);
}

Bytes cobs(const Bytes& in) {
  Bytes out(in.size() + in.size() / 254 + 1);
  size_t n = hfp::cobsEncode(in.empty() ? NULL : &in[0], in.size(), &out[0]);
  out.resize(n);
  return out;
}

Bytes range(int from, int to) {  // from..to inclusive, as bytes
  Bytes b;
  for (int v = from; v <= to; v++) b.push_back((uint8_t)v);
  return b;
}

Bytes concat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

void cobs_wikipediaExamples_encodeCanonically() {
  // The examples of the COBS article (without the trailing delimiter).
  const uint8_t e1[] = {0x01, 0x01};
  CHECK(cobs(Bytes(1, 0x00)) == Bytes(e1, e1 + 2));
  const uint8_t i2[] = {0x00, 0x00}, e2[] = {0x01, 0x01, 0x01};
  CHECK(cobs(Bytes(i2, i2 + 2)) == Bytes(e2, e2 + 3));
  const uint8_t i3[] = {0x00, 0x11, 0x00}, e3[] = {0x01, 0x02, 0x11, 0x01};
  CHECK(cobs(Bytes(i3, i3 + 3)) == Bytes(e3, e3 + 4));
  const uint8_t i4[] = {0x11, 0x22, 0x00, 0x33}, e4[] = {0x03, 0x11, 0x22, 0x02, 0x33};
  CHECK(cobs(Bytes(i4, i4 + 4)) == Bytes(e4, e4 + 5));
  const uint8_t i5[] = {0x11, 0x22, 0x33, 0x44}, e5[] = {0x05, 0x11, 0x22, 0x33, 0x44};
  CHECK(cobs(Bytes(i5, i5 + 4)) == Bytes(e5, e5 + 5));
  const uint8_t i6[] = {0x11, 0x00, 0x00, 0x00}, e6[] = {0x02, 0x11, 0x01, 0x01, 0x01};
  CHECK(cobs(Bytes(i6, i6 + 4)) == Bytes(e6, e6 + 5));
  // 01..FE (254 bytes): one full block, no trailing 0x01.
  CHECK(cobs(range(1, 254)) == concat(Bytes(1, 0xFF), range(1, 254)));
  // 00..FE (255 bytes).
  CHECK(cobs(range(0, 254)) == concat(concat(Bytes(1, 0x01), Bytes(1, 0xFF)), range(1, 254)));
  // 01..FF (255 bytes).
  const uint8_t tail9[] = {0x02, 0xFF};
  CHECK(cobs(range(1, 255)) == concat(concat(Bytes(1, 0xFF), range(1, 254)), Bytes(tail9, tail9 + 2)));
  // 02..FF 00 (255 bytes).
  const uint8_t tail10[] = {0x01, 0x01};
  CHECK(cobs(concat(range(2, 255), Bytes(1, 0))) == concat(concat(Bytes(1, 0xFF), range(2, 255)), Bytes(tail10, tail10 + 2)));
  // 03..FF 00 01 (255 bytes).
  const uint8_t tail11[] = {0x02, 0x01};
  const uint8_t i11tail[] = {0x00, 0x01};
  CHECK(cobs(concat(range(3, 255), Bytes(i11tail, i11tail + 2))) == concat(concat(Bytes(1, 0xFE), range(3, 255)), Bytes(tail11, tail11 + 2)));
}

// ---- Decoder robustness -----------------------------------------------------------------------

Bytes setOutputsCommand(uint16_t sequence, uint8_t first, const uint16_t* values, size_t count) {
  hfp::FrameWriter writer(sequence);
  writer.begin(hfp::TYPE_SET_OUTPUTS);
  writer.u8(first);
  for (size_t i = 0; i < count; i++) writer.u16(values[i]);
  return encode(writer);
}

void decoder_garbageBeforeFrames_resynchronisesOnDelimiter() {
  const uint16_t values[] = {500, 0};
  Bytes first = setOutputsCommand(1, 0, values, 2);
  Bytes second = setOutputsCommand(2, 0, values, 2);
  Bytes stream = concat(concat(asBytes("GARBAGE!"), first), second);
  hfp::FrameDecoder decoder;
  Decoded d = decodeAll(stream, decoder);
  // The garbage has no zero, so it swallows the first frame; the second decodes.
  CHECK(d.bad == 1);
  CHECK(d.frames.size() == 1);
  CHECK(d.frames.size() == 1 && d.frames[0].sequence == 2);
  CHECK(decoder.droppedBytes() == 8 + first.size());
}

void decoder_oneByteAtATime_matchesWholeBuffer() {
  const uint16_t values[] = {1, 2, 3, 4, 5};
  Bytes stream = concat(setOutputsCommand(7, 0, values, 5), setOutputsCommand(8, 2, values, 3));
  hfp::FrameDecoder decoder;
  int frames = 0;
  for (size_t i = 0; i < stream.size(); i++) {
    if (decoder.feed(stream[i]) == hfp::FrameDecoder::FRAME) {
      frames++;
      CHECK(decoder.frame().type == hfp::TYPE_SET_OUTPUTS);
      CHECK(decoder.frame().sequence == 6 + frames);
      CHECK(decoder.frame().payloadLength == (frames == 1 ? 11u : 7u));
    }
  }
  CHECK(frames == 2);
}

void decoder_overlongAndShortFrames_areBadFrames() {
  hfp::FrameDecoder decoder;
  Bytes overlong(300, 0x01);  // 300 code bytes of 1: 299 zeros decoded, more than MAX_FRAME
  overlong.push_back(0);
  Decoded d = decodeAll(overlong, decoder);
  CHECK(d.bad == 1);
  CHECK(decoder.droppedBytes() == 301);
  const uint8_t shortFrame[] = {0x03, 0x01, 0x02, 0x00};  // decodes to 2 bytes: shorter than header + CRC
  d = decodeAll(Bytes(shortFrame, shortFrame + 4), decoder);
  CHECK(d.bad == 1);
  CHECK(decoder.badFrames() == 2);
}

// ---- Device behaviour ---------------------------------------------------------------------------

const uint8_t REFERENCE_UNITS[] = {0, 0, 0, 2, 4};
hfp::DeviceConfig referenceConfig() {
  hfp::DeviceConfig c = {1, 0, 0, 12, 1000, 4000, 5, 5, REFERENCE_UNITS, "hapticon-ref"};
  return c;
}

void device_outOfRangeCommand_changesNoOutput() {
  hfp::DeviceConfig config = referenceConfig();
  CaptureSink sink;
  RecordingOutputs outputs;
  hfp::Device device(config, sink, outputs);
  const uint16_t good[] = {100, 200, 300};
  Bytes command = setOutputsCommand(1, 0, good, 3);
  device.receive(&command[0], command.size());
  CHECK(outputs.calls == 3);
  CHECK(device.output(0) == 100 && device.output(1) == 200 && device.output(2) == 300);
  const uint16_t bad[] = {999, 1000, 1001};
  command = setOutputsCommand(2, 0, bad, 3);
  device.receive(&command[0], command.size());
  CHECK(outputs.calls == 3);
  CHECK(device.output(0) == 100 && device.output(1) == 200 && device.output(2) == 300);
  hfp::FrameDecoder decoder;
  Decoded answers = decodeAll(sink.data, decoder);
  CHECK(answers.frames.size() == 2);
  if (answers.frames.size() == 2) {
    const uint8_t ok[] = {1, 0, hfp::ACK_OK, 0};
    const uint8_t nack[] = {2, 0, hfp::NACK_OUT_OF_RANGE, 2};
    CHECK(answers.payloads[0] == Bytes(ok, ok + 4));
    CHECK(answers.payloads[1] == Bytes(nack, nack + 4));
    CHECK(answers.frames[0].sequence == 0 && answers.frames[1].sequence == 1);
  }
}

Bytes stimulateCommand(uint16_t sequence, const uint8_t* payload, size_t length) {
  hfp::FrameWriter writer(sequence);
  writer.begin(hfp::TYPE_STIMULATE);
  for (size_t i = 0; i < length; i++) writer.u8(payload[i]);
  return encode(writer);
}

// The acks the host's CommandWriter matches by sequence number: a STIMULATE at the 2.7 mA cap (step 200) is
// acknowledged and plays; one step past it, a 0 ms stimulus and a short payload are refused with the reason the
// host shows (OUT_OF_RANGE with grains.h's ParamError 5 and 9, MALFORMED), and nothing more plays.
void device_stimulate_acksAtTheCap_nacksPastItWithTheReason() {
  hfp::DeviceConfig config = referenceConfig();
  CaptureSink sink;
  RecordingOutputs outputs;
  hgr::GrainRenderer grains;
  hfp::Device device(config, sink, outputs, 0, &grains);
  const uint8_t atCap[] = {8, 200, 200, 0};
  const uint8_t pastCap[] = {8, 201, 200, 0};
  const uint8_t noTime[] = {8, 100, 0, 0};
  const uint8_t shortPayload[] = {8, 100, 200};
  Bytes commands = concat(concat(stimulateCommand(5, atCap, 4), stimulateCommand(6, pastCap, 4)),
                          concat(stimulateCommand(7, noTime, 4), stimulateCommand(8, shortPayload, 3)));
  device.receive(&commands[0], commands.size());
  CHECK(grains.stimulating());
  hfp::FrameDecoder decoder;
  Decoded answers = decodeAll(sink.data, decoder);
  CHECK(answers.frames.size() == 4);
  if (answers.frames.size() == 4) {
    const uint8_t expected[4][4] = {
        {5, 0, hfp::ACK_OK, 0},
        {6, 0, hfp::NACK_OUT_OF_RANGE, hgr::STEP_ABOVE_CAP},
        {7, 0, hfp::NACK_OUT_OF_RANGE, hgr::BAD_DURATION},
        {8, 0, hfp::NACK_MALFORMED, 0},
    };
    for (int i = 0; i < 4; i++) {
      CHECK(answers.frames[i].type == hfp::TYPE_ACK);
      CHECK(answers.payloads[i] == Bytes(expected[i], expected[i] + 4));
    }
  }
}

void device_begin_sendsDelimiterThenDeviceInfo() {
  hfp::DeviceConfig config = referenceConfig();
  CaptureSink sink;
  RecordingOutputs outputs;
  hfp::Device device(config, sink, outputs);
  device.begin();
  CHECK(!sink.data.empty() && sink.data[0] == 0);
  hfp::FrameDecoder decoder;
  Decoded d = decodeAll(sink.data, decoder);
  CHECK(d.frames.size() == 1 && d.frames[0].type == hfp::TYPE_DEVICE_INFO && d.frames[0].sequence == 0);
  CHECK(decoder.droppedBytes() == 1);
}

void device_sampleDue_keepsTheGridAndRestartsAfterAStall() {
  hfp::DeviceConfig config = referenceConfig();
  CaptureSink sink;
  RecordingOutputs outputs;
  hfp::Device device(config, sink, outputs);
  uint32_t t0 = 0xFFFFF000u;  // 4096 us before micros() wraps
  CHECK(device.sampleDue(t0));
  CHECK(!device.sampleDue(t0 + 999));
  CHECK(device.sampleDue(t0 + 1003));  // 3 us late: stays on the grid
  CHECK(!device.sampleDue(t0 + 1999));
  CHECK(device.sampleDue(t0 + 2000));
  CHECK(device.sampleDue(t0 + 5000));  // across the wrap; also over a period late: restart from here
  CHECK(!device.sampleDue(t0 + 5999));
  CHECK(device.sampleDue(t0 + 6000));
}

void device_setSampleRate_changesThePeriod() {
  hfp::DeviceConfig config = referenceConfig();
  CaptureSink sink;
  RecordingOutputs outputs;
  hfp::Device device(config, sink, outputs);
  hfp::FrameWriter writer(5);
  writer.begin(hfp::TYPE_SET_SAMPLE_RATE);
  writer.u32(250);
  Bytes command = encode(writer);
  device.receive(&command[0], command.size());
  CHECK(device.sampleRateHz() == 250);
  CHECK(device.sampleDue(0));
  CHECK(!device.sampleDue(3999));
  CHECK(device.sampleDue(4000));
}

// ---- Shared vectors -----------------------------------------------------------------------------

struct VectorDevice {
  hfp::DeviceConfig config;
  std::vector<uint8_t> units;
  std::string name;
};

void encodeFrameVector(const std::vector<std::string>& t, const std::string& expectedHex) {
  // frame <name> <type> <sequence> <args...> = <hex>
  const std::string& name = t[1];
  const std::string& type = t[2];
  hfp::FrameWriter writer((uint16_t)strtoul(t[3].c_str(), NULL, 10));
  std::vector<unsigned long> args;
  for (size_t i = 4; i < t.size() && t[i] != "="; i++) {
    if (type == "info" && i == 10) continue;  // units list, handled below
    if (type == "info" && i == 11) continue;  // name
    if (t[i] != "-") args.push_back(strtoul(t[i].c_str(), NULL, 10));
  }
  if (type == "sample") {
    writer.begin(hfp::TYPE_SAMPLE);
    writer.u32((uint32_t)args[0]);
    for (size_t i = 1; i < args.size(); i++) writer.u16((uint16_t)args[i]);
  } else if (type == "info") {
    writer.begin(hfp::TYPE_DEVICE_INFO);
    std::vector<unsigned long> units = numbers(t[10]);
    std::string deviceName = t[11] == "-" ? "" : t[11];
    for (size_t i = 0; i < 4; i++) writer.u8((uint8_t)args[i]);
    writer.u32((uint32_t)args[4]);
    writer.u8((uint8_t)units.size());
    writer.u8((uint8_t)args[5]);
    for (size_t i = 0; i < units.size(); i++) writer.u8((uint8_t)units[i]);
    for (size_t i = 0; i < deviceName.size(); i++) writer.u8((uint8_t)deviceName[i]);
  } else if (type == "ack") {
    writer.begin(hfp::TYPE_ACK);
    writer.u16((uint16_t)args[0]);
    writer.u8((uint8_t)args[1]);
    writer.u8((uint8_t)args[2]);
  } else if (type == "set-outputs") {
    writer.begin(hfp::TYPE_SET_OUTPUTS);
    writer.u8((uint8_t)args[0]);
    for (size_t i = 1; i < args.size(); i++) writer.u16((uint16_t)args[i]);
  } else if (type == "request-info") {
    writer.begin(hfp::TYPE_REQUEST_INFO);
  } else if (type == "set-sample-rate") {
    writer.begin(hfp::TYPE_SET_SAMPLE_RATE);
    writer.u32((uint32_t)args[0]);
  } else {
    fprintf(stderr, "unknown frame type %s in vector %s\n", type.c_str(), name.c_str());
    failures++;
    return;
  }
  Bytes expected = unhex(expectedHex);
  checkBytes("frame vector", name, encode(writer), expected);
  // And the decoder reads it back, one byte at a time.
  hfp::FrameDecoder decoder;
  Decoded d = decodeAll(expected, decoder);
  CHECK(d.frames.size() == 1 && d.bad == 0);
  if (d.frames.size() == 1) CHECK(d.frames[0].sequence == strtoul(t[3].c_str(), NULL, 10));
}

void runExchange(const VectorDevice& vd, const std::vector<std::string>& t) {
  // exchange <name> <expected> <command hex> = <answer hex or ->
  CaptureSink sink;
  RecordingOutputs outputs;
  hfp::Device device(vd.config, sink, outputs);
  Bytes command = unhex(t[3]);
  device.receive(&command[0], command.size());
  checkBytes("exchange", t[1], sink.data, unhex(t[5]));
  if (t[2] != "OK") CHECK(outputs.calls == 0);
}

int runVectors(const char* path) {
  std::ifstream in(path);
  if (!in) {
    fprintf(stderr, "cannot read %s\n", path);
    return 2;
  }
  VectorDevice vd;
  bool haveDevice = false;
  int frameVectors = 0, exchanges = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::vector<std::string> t;
    std::string w;
    while (words >> w) t.push_back(w);
    if (t[0] == "device") {
      std::vector<unsigned long> units = numbers(t[8]);
      vd.units.assign(units.begin(), units.end());
      vd.name = t[9];
      hfp::DeviceConfig c = {(uint8_t)atoi(t[1].c_str()), (uint8_t)atoi(t[2].c_str()), (uint8_t)atoi(t[3].c_str()),
                             (uint8_t)atoi(t[4].c_str()), (uint32_t)strtoul(t[5].c_str(), NULL, 10),
                             (uint32_t)strtoul(t[6].c_str(), NULL, 10), (uint8_t)vd.units.size(), (uint8_t)atoi(t[7].c_str()),
                             &vd.units[0], vd.name.c_str()};
      vd.config = c;
      haveDevice = true;
    } else if (t[0] == "frame") {
      encodeFrameVector(t, t.back());
      frameVectors++;
    } else if (t[0] == "exchange") {
      CHECK(haveDevice);
      if (haveDevice) runExchange(vd, t);
      exchanges++;
    }
  }
  CHECK(frameVectors >= 10);
  CHECK(exchanges >= 10);
  printf("shared vectors: %d frames, %d exchanges\n", frameVectors, exchanges);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: host_test <framed-vectors.txt>\n");
    return 2;
  }
  crc16_checkValue_is29B1();
  cobs_wikipediaExamples_encodeCanonically();
  decoder_garbageBeforeFrames_resynchronisesOnDelimiter();
  decoder_oneByteAtATime_matchesWholeBuffer();
  decoder_overlongAndShortFrames_areBadFrames();
  device_outOfRangeCommand_changesNoOutput();
  device_stimulate_acksAtTheCap_nacksPastItWithTheReason();
  device_begin_sendsDelimiterThenDeviceInfo();
  device_sampleDue_keepsTheGridAndRestartsAfterAStall();
  device_setSampleRate_changesThePeriod();
  if (runVectors(argv[1]) != 0) return 2;
  printf("host_test: %d checks, %d failed\n", checks, failures);
  return failures == 0 ? 0 : 1;
}
