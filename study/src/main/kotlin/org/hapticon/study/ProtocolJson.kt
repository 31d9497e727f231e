package org.hapticon.study

import org.hapticon.core.IconValidationException
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonArray
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonNull
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue
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
    /** The value of the `schema` member. */
    public const val SCHEMA: String = "hapticon.study"

    /** The schema version this build writes and reads. */
    public const val VERSION: Int = 1

    /** [protocol] as a JSON object, members in schema order. Does not throw. */
    public fun toJsonValue(protocol: StudyProtocol): JsonObject = JsonObject(
        linkedMapOf(
            "schema" to JsonString(SCHEMA),
            "version" to JsonNumber(VERSION),
            "id" to JsonString(protocol.id),
            "revision" to JsonNumber(protocol.revision),
            "title" to JsonString(protocol.title),
            "envelopeModel" to JsonString(modelName(protocol.envelopeModel)),
            "participants" to (protocol.participants?.let { JsonNumber(it) } ?: JsonNull),
            "masking" to JsonString(protocol.masking.jsonName),
            "scale" to JsonObject(
                linkedMapOf("points" to JsonNumber(protocol.scale.points), "labels" to JsonArray(protocol.scale.labels.map(::JsonString))),
            ),
            "taskOrder" to JsonString(protocol.taskOrder.jsonName),
            "fixedFirst" to JsonArray(protocol.fixedFirst.map(::JsonString)),
            "tasks" to JsonArray(protocol.tasks.map(::taskJson)),
        ),
    )

    /**
     * The protocol [value] describes. Throws [ProtocolException] naming the path of the first problem: not an
     * object, wrong schema or version, a missing or mistyped member, an invalid icon, or a protocol
     * [StudyProtocol] rejects.
     */
    public fun fromJsonValue(value: JsonValue): StudyProtocol {
        val doc = JsonFields.of(value, "", "protocol")
        doc.requireSchema(SCHEMA, VERSION)
        val scale = doc.obj("scale")
        return StudyProtocol(
            id = doc.string("id"),
            revision = doc.optionalInt("revision") ?: 1,
            title = doc.string("title"),
            envelopeModel = model(doc),
            participants = doc.optionalInt("participants"),
            masking = named(doc, "masking", Masking.NONE, Masking.entries.map { it.jsonName }, Masking::fromJsonName),
            scale = LikertScale(scale.int("points"), scale.strings("labels") ?: emptyList()),
            taskOrder = scheme(doc, "taskOrder"),
            fixedFirst = doc.strings("fixedFirst") ?: emptyList(),
            tasks = doc.objects("tasks") { task ->
                StudyTask(
                    id = task.string("id"),
                    title = task.string("title"),
                    instructions = task.optionalString("instructions") ?: "",
                    question = task.string("question"),
                    stimulusOrder = scheme(task, "stimulusOrder"),
                    presentation = named(task, "presentation", TaskPresentation.PER_TRIAL, TaskPresentation.entries.map { it.jsonName }, TaskPresentation::fromJsonName),
                    stimuli = task.objects("stimuli") { stimulus ->
                        Stimulus(
                            id = stimulus.string("id"),
                            icon = icon(stimulus),
                            text = stimulus.optionalString("text"),
                            sticker = stimulus.optionalString("sticker"),
                            label = stimulus.optionalString("label"),
                            number = stimulus.optionalInt("number"),
                        )
                    },
                )
            },
        )
    }

    /** [protocol] as JSON text: compact when [indent] is empty, else indented. Does not throw for a valid [indent]. */
    public fun encode(protocol: StudyProtocol, indent: String = "  "): String = Json.encode(toJsonValue(protocol), indent)

    /**
     * Parses a protocol from [text]. Throws [JsonException] when [text] is not valid JSON (or over
     * [Json.DEFAULT_MAX_LENGTH]), and [ProtocolException] as [fromJsonValue] does.
     */
    public fun decode(text: String): StudyProtocol = fromJsonValue(Json.decode(text))

    private fun taskJson(task: StudyTask): JsonObject = JsonObject(
        linkedMapOf(
            "id" to JsonString(task.id),
            "title" to JsonString(task.title),
            "instructions" to JsonString(task.instructions),
            "question" to JsonString(task.question),
            "stimulusOrder" to JsonString(task.stimulusOrder.jsonName),
            "presentation" to JsonString(task.presentation.jsonName),
            "stimuli" to JsonArray(task.stimuli.map(::stimulusJson)),
        ),
    )

    private fun stimulusJson(stimulus: Stimulus): JsonObject {
        val members = linkedMapOf<String, JsonValue>("id" to JsonString(stimulus.id))
        // Absent rather than null: the protocol file is edited by hand, and fewer members read better.
        stimulus.text?.let { members["text"] = JsonString(it) }
        stimulus.sticker?.let { members["sticker"] = JsonString(it) }
        stimulus.label?.let { members["label"] = JsonString(it) }
        stimulus.number?.let { members["number"] = JsonNumber(it) }
        members["icon"] = IconJson.toJsonValue(stimulus.icon)
        return JsonObject(members)
    }

    private fun icon(stimulus: JsonFields) = try {
        IconJson.fromJsonValue(stimulus.optional("icon") ?: stimulus.missing("icon"))
    } catch (e: IconValidationException) {
        val path = stimulus.at("icon")
        throw ProtocolException(if (e.field == "icon") path else "$path.${e.field}", e.message.orEmpty().removePrefix("${e.field}: "))
    }

    /** The JSON (and CSV, CLI) name of [model]: `paper` or `processing`. */
    public fun modelName(model: EnvelopeModel): String = model.name.lowercase()

    private fun model(fields: JsonFields): EnvelopeModel =
        named(fields, "envelopeModel", EnvelopeModel.DEFAULT, EnvelopeModel.entries.map(::modelName)) { name ->
            EnvelopeModel.entries.firstOrNull { modelName(it) == name }
        }

    private fun <T> named(fields: JsonFields, member: String, default: T, names: List<String>, parse: (String) -> T?): T {
        val name = fields.optionalString(member) ?: return default
        return parse(name) ?: throw ProtocolException(fields.at(member), "expected ${names.joinToString(", ") { "\"$it\"" }}, got \"${name.take(40)}\"")
    }

    private fun scheme(fields: JsonFields, member: String): OrderScheme {
        val name = fields.optionalString(member) ?: return OrderScheme.FIXED
        return OrderScheme.fromJsonName(name) ?: throw ProtocolException(
            fields.at(member), "expected ${OrderScheme.entries.joinToString(", ") { "\"${it.jsonName}\"" }}, got \"${name.take(40)}\"",
        )
    }
}
