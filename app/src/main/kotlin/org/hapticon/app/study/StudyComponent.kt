package org.hapticon.app.study

import android.content.Context
import java.io.File

/** Everything the user-study feature needs, built once in the [org.hapticon.app.di.AppContainer]. */
class StudyComponent(
    val repository: StudyRepository,
    val settings: StudySettingsRepository,
    val pin: PinGate,
    val noise: MaskingNoisePlayer,
    val headphones: HeadphoneDetector,
    val exporter: StudyExporter,
    val uploader: ResultUploader,
    /** Event timestamps, epoch ms. */
    val clock: () -> Long = System::currentTimeMillis,
) {
    companion object {
        /** The production component on [db]: exports go to cacheDir/exports, noise files to cacheDir/masking-noise. */
        fun create(context: Context, db: StudyDatabase): StudyComponent = StudyComponent(
            repository = RoomStudyRepository(db),
            settings = SharedPreferencesStudySettings(context),
            pin = PinGate(context),
            noise = Media3MaskingNoisePlayer(context.applicationContext, NoiseFiles(File(context.cacheDir, "masking-noise"))),
            headphones = AudioManagerHeadphoneDetector(context),
            exporter = StudyExporter(File(context.cacheDir, "exports")),
            uploader = HttpResultUploader(),
        )
    }
}
