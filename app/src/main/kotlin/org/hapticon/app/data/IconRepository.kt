package org.hapticon.app.data

import kotlinx.coroutines.flow.Flow
import org.hapticon.core.HapticIcon

/** The haptic icons a user can pick from. */
interface IconRepository {
    /** Every available icon, presets first; emits again when the set changes. */
    fun icons(): Flow<List<HapticIcon>>
}
