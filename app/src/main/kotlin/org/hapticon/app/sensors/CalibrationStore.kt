package org.hapticon.app.sensors

import android.content.Context
import android.content.SharedPreferences
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.FlexFit
import org.hapticon.sensor.glove.GloveFinger

/** A finger's calibration as kept for a user, with the fit quality it came with. */
data class SavedCalibration(
    val calibration: FlexCalibration,
    val rSquared: Double,
    val rmsAngleErrorDegrees: Double,
    val savedAtMillis: Long,
) {
    companion object {
        fun of(fit: FlexFit, nowMillis: Long) = SavedCalibration(fit.calibration, fit.rSquared, fit.rmsAngleErrorDegrees, nowMillis)
    }
}

/**
 * Flex-sensor calibrations per user (a study participant) and finger, and who is the current user.
 * SharedPreferences for now; a Room table replaces it with the next task.
 */
interface CalibrationStore {
    /** The user whose glove is on; never blank. */
    val currentUser: StateFlow<String>

    /** Bumped on every save, so screens can reload. */
    val revision: StateFlow<Long>

    fun setCurrentUser(user: String)

    fun load(user: String, finger: GloveFinger): SavedCalibration?

    fun save(user: String, finger: GloveFinger, calibration: SavedCalibration)

    /** [user]'s calibration for [finger], or the study's mean when there is none. */
    fun calibrationFor(user: String, finger: GloveFinger): FlexCalibration =
        load(user, finger)?.calibration ?: FlexCalibration.defaultFor(finger)

    companion object {
        const val DEFAULT_USER = "participant-1"
    }
}

/** [CalibrationStore] in SharedPreferences: `user/FINGER/alpha` etc., doubles as exact strings. */
class SharedPreferencesCalibrationStore(private val prefs: SharedPreferences) : CalibrationStore {
    constructor(context: Context) : this(context.getSharedPreferences(FILE, Context.MODE_PRIVATE))

    private val user = MutableStateFlow(prefs.getString(KEY_CURRENT_USER, null)?.takeIf { it.isNotBlank() } ?: CalibrationStore.DEFAULT_USER)
    private val saves = MutableStateFlow(0L)

    override val currentUser: StateFlow<String> = user.asStateFlow()
    override val revision: StateFlow<Long> = saves.asStateFlow()

    override fun setCurrentUser(user: String) {
        val name = user.trim().ifEmpty { CalibrationStore.DEFAULT_USER }
        prefs.edit().putString(KEY_CURRENT_USER, name).apply()
        this.user.value = name
    }

    override fun load(user: String, finger: GloveFinger): SavedCalibration? {
        val prefix = prefix(user, finger)
        val alpha = prefs.getString("$prefix/alpha", null)?.toDoubleOrNull() ?: return null
        val beta = prefs.getString("$prefix/beta", null)?.toDoubleOrNull() ?: return null
        val calibration = runCatching { FlexCalibration(alpha, beta) }.getOrNull() ?: return null
        return SavedCalibration(
            calibration = calibration,
            rSquared = prefs.getString("$prefix/r2", null)?.toDoubleOrNull() ?: Double.NaN,
            rmsAngleErrorDegrees = prefs.getString("$prefix/rms", null)?.toDoubleOrNull() ?: Double.NaN,
            savedAtMillis = prefs.getLong("$prefix/at", 0),
        )
    }

    override fun save(user: String, finger: GloveFinger, calibration: SavedCalibration) {
        val prefix = prefix(user, finger)
        prefs.edit()
            .putString("$prefix/alpha", calibration.calibration.alphaPerDegree.toString())
            .putString("$prefix/beta", calibration.calibration.betaKiloohms.toString())
            .putString("$prefix/r2", calibration.rSquared.toString())
            .putString("$prefix/rms", calibration.rmsAngleErrorDegrees.toString())
            .putLong("$prefix/at", calibration.savedAtMillis)
            .apply()
        saves.value++
    }

    private fun prefix(user: String, finger: GloveFinger) = "calibration/${user.replace('/', '_')}/${finger.name}"

    private companion object {
        const val FILE = "glove_calibrations"
        const val KEY_CURRENT_USER = "current_user"
    }
}
