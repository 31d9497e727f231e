package org.hapticon.app.gesture

import kotlinx.coroutines.flow.StateFlow
import org.hapticon.gesture.social.SocialTouchModel
import java.io.File

/** Where the social-touch model lives: one model at a time, trained in the app or made by `hapticon train --classifier logitboost`. */
interface SocialTouchModelStore {
    /** The stored model, or null when there is none (or it no longer decodes); read from storage on first use, so not on the main thread. */
    val model: StateFlow<SocialTouchModel?>

    /** Stores [model], replacing the previous one. */
    fun save(model: SocialTouchModel)

    /** Decodes [text] (a `hapticon train --classifier logitboost` model file) and stores it; [IllegalArgumentException] saying what is wrong. */
    fun import(text: String): SocialTouchModel = SocialTouchModel.decode(text).also { save(it) }
}

/** The model as JSON ([SocialTouchModel.encode]) in [file]. */
class FileSocialTouchModelStore(file: File) : SocialTouchModelStore {
    private val store = FileModelStore(file, { SocialTouchModel.decode(it) }) { it.encode() }

    override val model: StateFlow<SocialTouchModel?> get() = store.model

    override fun save(model: SocialTouchModel) = store.save(model)
}
