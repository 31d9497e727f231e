package org.hapticon.core.render

/**
 * How closely a rendered output reproduces the ideal (exact, double precision) signal.
 *
 * Errors are in signal units (full scale = 1.0), measured sample by sample over the whole render.
 *
 * @property rmsError root-mean-square of (rendered − ideal) over all samples; 0.0 for an empty render.
 * @property maxError largest |rendered − ideal| over all samples; 0.0 for an empty render.
 * @property description a short human-readable note on how the output was produced (e.g. "PCM16 at 48000 Hz").
 */
public data class Fidelity(val rmsError: Double, val maxError: Double, val description: String)
