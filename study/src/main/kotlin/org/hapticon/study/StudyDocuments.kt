package org.hapticon.study

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaReport

/** A study protocol, schema `hapticon.study` ([ProtocolJson]); members in schema order, defaults as documented there. */
@Serializable
internal class ProtocolDocument(
    val schema: String,
    val version: Long,
    val id: String,
    val revision: Int = 1,
    val title: String,
    val envelopeModel: String? = null,
    val participants: Int? = null,
    val masking: String? = null,
    val scale: ScaleDocument,
    val taskOrder: String? = null,
    val fixedFirst: List<String> = emptyList(),
    val tasks: List<TaskDocument>,
)

/** The answer scale of a [ProtocolDocument]. */
@Serializable
internal class ScaleDocument(val points: Int, val labels: List<String> = emptyList())

/** One task of a [ProtocolDocument]. */
@Serializable
internal class TaskDocument(
    val id: String,
    val title: String,
    val instructions: String = "",
    val question: String,
    val stimulusOrder: String? = null,
    val presentation: String? = null,
    val stimuli: List<StimulusDocument>,
)

/** One stimulus; its optional members are left out rather than written as null (the file is edited by hand). */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class StimulusDocument(
    val id: String,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val text: String? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val sticker: String? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val label: String? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val number: Int? = null,
    /** The icon in its own schema (`hapticon.icon`), read by [org.hapticon.core.io.IconJson]. */
    val icon: JsonElement,
)
