package org.hapticon.study

import org.hapticon.study.schema.ProtocolException
import org.hapticon.study.schema.StudyReport
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import org.hapticon.core.IconValidationException
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.study.design.OrderScheme

/**
 * Study protocols as JSON, schema `hapticon.study` version 1 (see docs/study.md):
 *
 * ```
 * {"schema": "hapticon.study", "version": 1, "id": "…", "revision": 1, "title": "…", "envelopeModel": "processing",
 *  "participants": 16, "masking": "white",
 *  "scale": {"points": 5, "labels": ["strongly disagree", …]}, "taskOrder": "paper", "fixedFirst": ["icons"],
 *  "tasks": [{"id": "…", "title": "…", "instructions": "…", "question": "Haptic icon {n} feels like {label}",
 *             "stimulusOrder": "williams", "presentation": "together",
 *             "stimuli": [{"id": "…", "number": 1, "text": "…", "sticker": "…", "label": "…",
 *             "icon": {icon JSON}}]}]}
 * ```
 *
 * Decoding is strict about what it uses and ignores unknown members. `revision` defaults to 1, `envelopeModel` to `processing`
 * (what the originating study's participants felt; `paper` is the trapezoid its text describes), `taskOrder` and
 * `stimulusOrder` to `fixed`, `participants` to none, `masking` to `none`, `presentation` to `per-trial`, `fixedFirst` and `labels` to empty, `instructions` to "". Every problem is a
 * [ProtocolException] whose path names the member, for example `tasks[0].stimuli[2].icon.attack`.
 */
public object ProtocolJson {
    /** The value of the `schema` member ([StudyFormats.PROTOCOL_SCHEMA]). */
    public const val SCHEMA: String = StudyFormats.PROTOCOL_SCHEMA

    /** The schema version this build writes and reads ([StudyFormats.PROTOCOL_VERSION]). */
    public const val VERSION: Int = StudyFormats.PROTOCOL_VERSION

    /** [protocol] as a JSON object, members in schema order. Does not throw. */
    public fun toJsonElement(protocol: StudyProtocol): JsonObject =
        SchemaJson.encodeToElement(ProtocolDocument.serializer(), document(protocol)) as JsonObject

    /**
     * The protocol [element] describes. Throws [ProtocolException] naming the path of the first problem: not an
     * object, wrong schema or version, a missing or mistyped member, an invalid icon, or a protocol
     * [StudyProtocol] rejects.
     */
    public fun fromJsonElement(element: JsonElement): StudyProtocol =
        protocol(SchemaJson.decode(ProtocolDocument.serializer(), element, StudyReport("protocol", mapOf("" to (SCHEMA to VERSION)))))

    /** [protocol] as JSON text: compact when [indent] is empty, else indented. Does not throw for a valid [indent]. */
    public fun encode(protocol: StudyProtocol, indent: String = "  "): String =
        SchemaJson.encode(ProtocolDocument.serializer(), document(protocol), indent)

    /**
     * Parses a protocol from [text]. Throws [JsonException] when [text] is not valid JSON (or over
     * [Json.DEFAULT_MAX_LENGTH]), and [ProtocolException] as [fromJsonElement] does.
     */
    public fun decode(text: String): StudyProtocol = fromJsonElement(Json.decode(text))

    internal fun document(protocol: StudyProtocol): ProtocolDocument = ProtocolDocument(
        schema = SCHEMA,
        version = VERSION.toLong(),
        id = protocol.id,
        revision = protocol.revision,
        title = protocol.title,
        envelopeModel = modelName(protocol.envelopeModel),
        participants = protocol.participants,
        masking = protocol.masking.jsonName,
        scale = ScaleDocument(protocol.scale.points, protocol.scale.labels),
        taskOrder = protocol.taskOrder.jsonName,
        fixedFirst = protocol.fixedFirst,
        tasks = protocol.tasks.map { task ->
            TaskDocument(
                task.id, task.title, task.instructions, task.question, task.stimulusOrder.jsonName, task.presentation.jsonName,
                task.stimuli.map { StimulusDocument(it.id, it.text, it.sticker, it.label, it.number, IconJson.toJsonElement(it.icon)) },
            )
        },
    )

    /** The protocol the checked [doc] describes; [ProtocolException]s name paths within the protocol document. */
    internal fun protocol(doc: ProtocolDocument): StudyProtocol {
        return StudyProtocol(
            id = doc.id,
            revision = doc.revision,
            title = doc.title,
            envelopeModel = named("envelopeModel", doc.envelopeModel, EnvelopeModel.DEFAULT, EnvelopeModel.entries.map(::modelName)) { name ->
                EnvelopeModel.entries.firstOrNull { modelName(it) == name }
            },
            participants = doc.participants,
            masking = named("masking", doc.masking, Masking.NONE, Masking.entries.map { it.jsonName }, Masking::fromJsonName),
            scale = LikertScale(doc.scale.points, doc.scale.labels),
            taskOrder = scheme("taskOrder", doc.taskOrder),
            fixedFirst = doc.fixedFirst,
            tasks = doc.tasks.mapIndexed { t, task ->
                val taskPath = "tasks[$t]"
                StudyTask(
                    id = task.id,
                    title = task.title,
                    instructions = task.instructions,
                    question = task.question,
                    stimulusOrder = scheme("$taskPath.stimulusOrder", task.stimulusOrder),
                    presentation = named(
                        "$taskPath.presentation", task.presentation, TaskPresentation.PER_TRIAL,
                        TaskPresentation.entries.map { it.jsonName }, TaskPresentation::fromJsonName,
                    ),
                    stimuli = task.stimuli.mapIndexed { s, stimulus ->
                        Stimulus(
                            id = stimulus.id,
                            icon = icon("$taskPath.stimuli[$s].icon", stimulus.icon),
                            text = stimulus.text,
                            sticker = stimulus.sticker,
                            label = stimulus.label,
                            number = stimulus.number,
                        )
                    },
                )
            },
        )
    }

    private fun icon(path: String, icon: JsonElement) = try {
        IconJson.fromJsonElement(icon)
    } catch (e: IconValidationException) {
        throw ProtocolException(if (e.field == "icon") path else "$path.${e.field}", e.message.orEmpty().removePrefix("${e.field}: "))
    }

    /** The JSON (and CSV, CLI) name of [model]: `paper` or `processing`. */
    public fun modelName(model: EnvelopeModel): String = model.name.lowercase()

    private fun <T> named(path: String, name: String?, default: T, names: List<String>, parse: (String) -> T?): T {
        if (name == null) return default
        return parse(name) ?: throw ProtocolException(path, "expected ${names.joinToString(", ") { "\"$it\"" }}, got \"${name.take(40)}\"")
    }

    private fun scheme(path: String, name: String?): OrderScheme =
        named(path, name, OrderScheme.FIXED, OrderScheme.entries.map { it.jsonName }, OrderScheme::fromJsonName)
}
