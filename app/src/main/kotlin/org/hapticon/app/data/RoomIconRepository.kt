package org.hapticon.app.data

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.app.data.database.IconDao
import org.hapticon.app.data.database.asEntity
import org.hapticon.app.data.database.asExternalModel
import org.hapticon.core.HapticIcon

/** The presets followed by the user's custom icons from Room; [save] stores a custom icon. */
class RoomIconRepository(private val dao: IconDao) : IconRepository {
    override fun icons(): Flow<List<HapticIcon>> = dao.icons().map { rows ->
        // A row that no longer validates (a stricter future rule) is skipped rather than crashing the picker.
        HapticIcon.PRESETS + rows.mapNotNull { runCatching { it.asExternalModel() }.getOrNull() }
            .filter { custom -> HapticIcon.PRESETS.none { it.name == custom.name } }
    }

    /** Stores [icon], replacing a custom icon of the same name. */
    suspend fun save(icon: HapticIcon) = dao.upsertIcon(icon.asEntity())
}
