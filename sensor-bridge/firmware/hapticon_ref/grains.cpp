#include "grains.h"

#include <math.h>

namespace hgr {

static uint8_t bitCount(uint16_t bits) {
  uint8_t n = 0;
  for (; bits != 0; bits &= (uint16_t)(bits - 1)) n++;
  return n;
}

uint32_t deliveryMicros(uint16_t electrodeBits) {
  return (PULSES_PER_GRAIN - 1) * PULSE_PERIOD_MICROS + (uint32_t)bitCount(electrodeBits) * SLOT_MICROS;
}

GrainParams defaultParams(uint8_t adcBits) {
  GrainParams p;
  p.grains = 24;
  p.distribution = LINEAR;
  p.minForce = 0;
  // The raw channel's full scale, as the device info announces it (adcBits 1..16).
  p.maxForce = adcBits >= 16 ? 0xFFFF : (uint16_t)((1u << adcBits) - 1);
  p.electrodeBits = 0x1FF;
  for (uint8_t i = 0; i < ELECTRODES; i++) p.steps[i] = 0;
  p.cutoffDeciHz = 200;
  p.grainMicros = (uint16_t)deliveryMicros(p.electrodeBits);
  return p;
}

ParamError validate(const GrainParams& p, uint32_t sampleRateHz) {
  if (p.grains > MAX_GRAINS) return BAD_GRAINS;
  if (p.distribution > CONCAVE) return BAD_DISTRIBUTION;
  if (p.minForce >= p.maxForce) return BAD_RANGE;
  if ((p.electrodeBits & ~0x1FFu) != 0 || bitCount(p.electrodeBits) < MIN_ELECTRODES) return TOO_FEW_ELECTRODES;
  for (uint8_t i = 0; i < ELECTRODES; i++) {
    if (p.steps[i] > AMPLITUDE_STEPS) return STEP_ABOVE_CAP;
  }
  // The cutoff must be above 0 and below Nyquist: 10 * cutoff(Hz) < 10 * rate / 2.
  if (p.cutoffDeciHz == 0 || (uint32_t)p.cutoffDeciHz * 2 >= sampleRateHz * 10) return BAD_CUTOFF;
  // No grain may start while one is being delivered: (PULSES - 1) periods plus a full scan of the electrodes.
  if (p.grainMicros < deliveryMicros(p.electrodeBits)) return BAD_GRAIN_LENGTH;
  return PARAMS_OK;
}

bool parseParams(const uint8_t* b, size_t length, GrainParams& p) {
  if (length != PARAMS_LENGTH) return false;
  p.grains = b[0];
  p.distribution = b[1];
  p.minForce = (uint16_t)(b[2] | (b[3] << 8));
  p.maxForce = (uint16_t)(b[4] | (b[5] << 8));
  p.electrodeBits = (uint16_t)(b[6] | (b[7] << 8));
  for (uint8_t i = 0; i < ELECTRODES; i++) p.steps[i] = b[8 + i];
  p.cutoffDeciHz = (uint16_t)(b[17] | (b[18] << 8));
  p.grainMicros = (uint16_t)(b[19] | (b[20] << 8));
  return true;
}

ParamError validate(const Stimulus& s) {
  if (s.electrode >= ELECTRODES) return BAD_ELECTRODE;
  if (s.step > AMPLITUDE_STEPS) return STEP_ABOVE_CAP;
  if (s.millis == 0 || s.millis > MAX_STIMULUS_MILLIS) return BAD_DURATION;
  return PARAMS_OK;
}

bool parseStimulus(const uint8_t* b, size_t length, Stimulus& s) {
  if (length != STIMULUS_LENGTH) return false;
  s.electrode = b[0];
  s.step = b[1];
  s.millis = (uint16_t)(b[2] | (b[3] << 8));
  return true;
}

GrainRenderer::GrainRenderer()
    : grainStart_(0), fired_(0), stimulus_(IDLE), stimStart_(0), stimPulses_(0), stimNext_(0) {
  stim_.electrode = 0;
  stim_.step = 0;
  stim_.millis = 0;
  configure(defaultParams(), 1000);
}

static float shape(uint8_t distribution, float x) {
  switch (distribution) {
    case CONVEX:
      return x * x;
    case CONCAVE:
      return sqrtf(x);
    default:
      return x;
  }
}

void GrainRenderer::configure(const GrainParams& p, uint32_t sampleRateHz) {
  params_ = p;
  uint8_t bins = (uint8_t)(p.grains + 1);  // grains = bins - 1
  for (uint8_t k = 0; k <= bins; k++) {
    // Both ends pinned, as GrainBins does.
    edges_[k] = k == 0 ? p.minForce : k == bins ? p.maxForce
                                                : p.minForce + (p.maxForce - p.minForce) * shape(p.distribution, (float)k / bins);
  }
  active_ = 0;
  for (uint8_t e = 0; e < ELECTRODES; e++) {
    if (p.electrodeBits & (1u << e)) order_[active_++] = e;
  }
  // a = 1 - e^(-2 pi fc / fs), the impulse-invariant RC filter of LowPassFilter.kt.
  alpha_ = 1.0f - expf(-2.0f * 3.14159265f * (p.cutoffDeciHz / 10.0f) / (float)sampleRateHz);
  filtered_ = 0;
  primed_ = false;
  reference_ = -1;
  playing_ = false;
  hasGrain_ = false;
  nextPulse_ = 0;
}

uint8_t GrainRenderer::binOf(float f) const {
  // Largest k in 0..grains with edge_k <= f (forces outside the range fall in the end bins).
  uint8_t lo = 0, hi = params_.grains;
  while (lo < hi) {
    uint8_t mid = (uint8_t)((lo + hi + 1) / 2);
    if (edges_[mid] <= f) lo = mid; else hi = (uint8_t)(mid - 1);
  }
  return lo;
}

bool GrainRenderer::offer(uint32_t nowMicros, uint16_t force) {
  if (!primed_) {
    filtered_ = force;
    primed_ = true;
  } else {
    filtered_ += alpha_ * ((float)force - filtered_);
  }
  int16_t bin = binOf(filtered_);
  if (stimulus_ != IDLE) {
    // A calibration stimulus has the array: follow the force without firing.
    reference_ = bin;
    return false;
  }
  if (reference_ < 0) {
    reference_ = bin;
    return false;
  }
  // Dead time: no grain within grainMicros of the last one's start (wrap-safe). A bin change during a
  // grain fires when it ends, if the bin still differs, as GrainDecider does.
  bool busy = playing_ || (hasGrain_ && (uint32_t)(nowMicros - grainStart_) < params_.grainMicros);
  if (busy || bin == reference_) return false;
  reference_ = bin;
  grainStart_ = nowMicros;
  playing_ = true;
  hasGrain_ = true;
  nextPulse_ = 0;
  fired_++;
  return true;
}

void GrainRenderer::stimulate(const Stimulus& s) {
  stim_ = s;
  // One pulse per started 8 ms period: 200 ms is 25 pulses, the last at 192 ms.
  stimPulses_ = (uint16_t)(((uint32_t)s.millis * 1000 + PULSE_PERIOD_MICROS - 1) / PULSE_PERIOD_MICROS);
  stimNext_ = 0;
  stimulus_ = PENDING;
  playing_ = false;  // a grain in progress gives way
}

uint8_t GrainRenderer::service(uint32_t nowMicros, Stimulator& out) {
  uint8_t emitted = 0;
  if (stimulus_ == PENDING) {
    stimStart_ = nowMicros;
    stimulus_ = PLAYING;
  }
  while (stimulus_ == PLAYING) {
    uint32_t onset = stimStart_ + (uint32_t)stimNext_ * PULSE_PERIOD_MICROS;
    if ((int32_t)(nowMicros - onset) < 0) return emitted;
    uint8_t step = stim_.step > AMPLITUDE_STEPS ? AMPLITUDE_STEPS : stim_.step;
    out.pulse(stim_.electrode, step, onset);
    emitted++;
    if (++stimNext_ >= stimPulses_) stimulus_ = IDLE;
  }
  while (playing_) {
    uint8_t p = (uint8_t)(nextPulse_ / active_), j = (uint8_t)(nextPulse_ % active_);
    uint32_t onset = grainStart_ + p * PULSE_PERIOD_MICROS + (uint32_t)j * SLOT_MICROS;
    if ((int32_t)(nowMicros - onset) < 0) break;
    uint8_t electrode = order_[j];
    // The cap again, at the last moment: a step above 200 (2.7 mA) never reaches the current source.
    uint8_t step = params_.steps[electrode] > AMPLITUDE_STEPS ? AMPLITUDE_STEPS : params_.steps[electrode];
    out.pulse(electrode, step, onset);
    emitted++;
    if (++nextPulse_ >= PULSES_PER_GRAIN * active_) playing_ = false;
  }
  return emitted;
}

}  // namespace hgr
