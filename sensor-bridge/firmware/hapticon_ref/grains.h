// Compliance grains rendered stand-alone on the board (no phone in the loop): the force channel is
// filtered and binned, and every bin change fires a grain of electrotactile pulses on the 3x3 array by
// time-division scanning. The Kotlin twin is org.hapticon.sensor.grains (GrainDecider, GrainBins) and
// org.hapticon.sensor.electrotactile (TimeDivisionScan, AmplitudeSteps); docs/sensor-models.md.
// Published rules (Shaping Compliance, CHI 2024): grains = bins - 1; 2 anodic 200 us pulses per grain at
// 125 Hz; each 200 us pulse followed by 50 us before the next electrode (a 4 kHz scan); amplitude in 200
// steps over 0-2.7 mA; fewer than 4 electrodes felt too weak; no grain starts while one is being delivered
// (003_8ca1dc8f53472543.txt:95-105, :123). Plain C++, no heap: builds with avr-gcc.
#ifndef HAPTICON_GRAINS_H
#define HAPTICON_GRAINS_H

#include <stddef.h>
#include <stdint.h>

namespace hgr {

const uint8_t MAX_GRAINS = 99;            // 100 bins, as GrainBins.MAX_COUNT
const uint8_t ELECTRODES = 9;             // the 3x3 array, index 3*row + column
const uint8_t MIN_ELECTRODES = 4;         // fewer felt too weak (Shaping Compliance's pilot, :107)
const uint8_t AMPLITUDE_STEPS = 200;      // step 200 = 2.7 mA, the absolute cap
const uint16_t PULSE_MICROS = 200;
const uint16_t GAP_MICROS = 50;
const uint16_t SLOT_MICROS = PULSE_MICROS + GAP_MICROS;  // 250 us: a 4 kHz scan
const uint8_t PULSES_PER_GRAIN = 2;
const uint32_t PULSE_PERIOD_MICROS = 8000;               // 125 Hz

enum Distribution { LINEAR = 0, CONVEX = 1, CONCAVE = 2 };

// Why a parameter set was refused (0 = accepted); hfp_device NACKs with it as the detail byte.
enum ParamError {
  PARAMS_OK = 0,
  BAD_GRAINS = 1,
  BAD_DISTRIBUTION = 2,
  BAD_RANGE = 3,
  TOO_FEW_ELECTRODES = 4,
  STEP_ABOVE_CAP = 5,
  BAD_CUTOFF = 6,
  BAD_GRAIN_LENGTH = 7,
  BAD_ELECTRODE = 8,
  BAD_DURATION = 9,
};

struct GrainParams {
  uint8_t grains;                // 0..MAX_GRAINS; bins = grains + 1
  uint8_t distribution;          // Distribution
  uint16_t minForce;             // range in the force channel's units (< maxForce)
  uint16_t maxForce;
  uint16_t electrodeBits;        // bit i = electrode i; at least MIN_ELECTRODES set, none above bit 8
  uint8_t steps[ELECTRODES];     // amplitude step per electrode, 0..AMPLITUDE_STEPS
  uint16_t cutoffDeciHz;         // low-pass cutoff in 0.1 Hz, below the Nyquist rate
  uint16_t grainMicros;          // no grain starts within this long of the last one (>= deliveryMicros(electrodeBits))
};

// Bytes of a SET_GRAINS payload: grains, distribution, min u16, max u16, bits u16, 9 steps, cutoff u16,
// grain length u16 (little-endian).
const size_t PARAMS_LENGTH = 21;

// How long one grain takes to deliver on the electrodes in bits: the second pulse starts 8 ms after the first and
// its scan takes 250 us per electrode (9.0 ms on 4 electrodes, 10.25 ms on 9). The paper's dead time: no grain
// starts while one is being delivered.
uint32_t deliveryMicros(uint16_t electrodeBits);

// The defaults: 24 grains, linear, the ADC's whole range (0..2^adcBits - 1, raw counts), the large square at step 0
// (nothing is felt until the host sends a calibrated level), 20 Hz, and a dead time of the grain's own delivery.
GrainParams defaultParams(uint8_t adcBits = 10);

// Checks p against the hard limits for a sensor sampled at sampleRateHz.
ParamError validate(const GrainParams& p, uint32_t sampleRateHz);

// Parses a SET_GRAINS payload; false when its length is wrong.
bool parseParams(const uint8_t* payload, size_t length, GrainParams& out);

// One calibration stimulus (Shaping Compliance, :152: each electrode alone, 200 ms, rising from 0.8 mA until clear
// and pain-free): the grain's pulses (200 us, anodic) every 8 ms (125 Hz) for millis on one electrode. One
// electrode is the point of it, so the 4-electrode minimum of grains does not apply; the 2.7 mA cap does.
struct Stimulus {
  uint8_t electrode;  // 0..ELECTRODES - 1
  uint8_t step;       // 0..AMPLITUDE_STEPS
  uint16_t millis;    // 1..MAX_STIMULUS_MILLIS
};

// The longest stimulus a command may ask for (the paper's is 200 ms): a stuck host cannot hold a current on.
const uint16_t MAX_STIMULUS_MILLIS = 1000;

// Bytes of a STIMULATE payload: electrode, step, duration u16 (little-endian, ms).
const size_t STIMULUS_LENGTH = 4;

// Checks s against the hard limits (electrode, 2.7 mA cap, duration).
ParamError validate(const Stimulus& s);

// Parses a STIMULATE payload; false when its length is wrong.
bool parseStimulus(const uint8_t* payload, size_t length, Stimulus& out);

// Where pulses go: the board's current source and electrode switches. step is 0..AMPLITUDE_STEPS.
class Stimulator {
 public:
  virtual void pulse(uint8_t electrode, uint8_t step, uint32_t onsetMicros) = 0;

 protected:
  ~Stimulator() {}
};

// The decider and the pulse scheduler. offer() one force sample at a time; service() as often as
// possible (at least every 250 us) to emit the pulses that are due. Not interrupt-safe.
class GrainRenderer {
 public:
  GrainRenderer();
  // Applies p (already validated) for a sensor at sampleRateHz; forgets the filter and the reference bin.
  void configure(const GrainParams& p, uint32_t sampleRateHz);
  // One force sample at nowMicros; true when a grain starts (its pulses begin at nowMicros).
  bool offer(uint32_t nowMicros, uint16_t force);
  // Plays s (already validated) from the next service() on, in place of any grain: grains are held off
  // (the reference bin follows the force silently) until it ends, so a press meanwhile fires nothing.
  void stimulate(const Stimulus& s);
  // True while a stimulus is pending or playing.
  bool stimulating() const { return stimulus_ != IDLE; }
  // Emits every pulse due by nowMicros, in time order; returns how many.
  uint8_t service(uint32_t nowMicros, Stimulator& out);
  // The bin of filtered force f (0..grains).
  uint8_t binOf(float f) const;
  const GrainParams& params() const { return params_; }
  uint32_t grainsFired() const { return fired_; }

 private:
  GrainParams params_;
  float edges_[MAX_GRAINS + 2];
  uint8_t order_[ELECTRODES];
  uint8_t active_;
  float alpha_;
  float filtered_;
  bool primed_;
  int16_t reference_;
  bool playing_;
  bool hasGrain_;  // a grain has started since configure()
  uint32_t grainStart_;
  uint8_t nextPulse_;  // index into the grain's PULSES_PER_GRAIN * active_ pulses
  uint32_t fired_;
  enum StimulusState { IDLE, PENDING, PLAYING };
  StimulusState stimulus_;
  Stimulus stim_;
  uint32_t stimStart_;
  uint16_t stimPulses_;  // pulses of the stimulus: one per started 8 ms of its length
  uint16_t stimNext_;
};

}  // namespace hgr

#endif
