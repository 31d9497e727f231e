package org.hapticon.gesture.recognition

import org.hapticon.core.io.JsonArray
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString

/** Typed access to members of a model's JSON, every problem an [IllegalArgumentException] naming the member. */
internal object JsonFields {
    fun array(obj: JsonObject, name: String, where: String = "model"): JsonArray =
        obj[name] as? JsonArray ?: throw IllegalArgumentException("$where: '$name' must be an array")

    fun string(obj: JsonObject, name: String, where: String = "model"): String =
        (obj[name] as? JsonString)?.value ?: throw IllegalArgumentException("$where: '$name' must be a string")

    fun number(obj: JsonObject, name: String, where: String = "model"): Double {
        val value = (obj[name] as? JsonNumber)?.value ?: throw IllegalArgumentException("$where: '$name' must be a number")
        require(value.isFinite()) { "$where: '$name' must be finite" }
        return value
    }

    fun int(obj: JsonObject, name: String, where: String = "model"): Int {
        val value = number(obj, name, where)
        require(value == Math.rint(value) && Math.abs(value) <= Int.MAX_VALUE) { "$where: '$name' must be a whole number, was $value" }
        return value.toInt()
    }

    fun ints(obj: JsonObject, name: String, where: String): IntArray = array(obj, name, where).elements.map {
        val v = (it as? JsonNumber)?.value
        require(v != null && v == Math.rint(v) && Math.abs(v) <= Int.MAX_VALUE) { "$where: '$name' must hold whole numbers" }
        v.toInt()
    }.toIntArray()

    fun doubles(obj: JsonObject, name: String, where: String): DoubleArray = array(obj, name, where).elements.map {
        val v = (it as? JsonNumber)?.value
        require(v != null && v.isFinite()) { "$where: '$name' must hold finite numbers" }
        v
    }.toDoubleArray()

    fun strings(obj: JsonObject, name: String, where: String = "model"): List<String> = array(obj, name, where).elements.map {
        (it as? JsonString)?.value ?: throw IllegalArgumentException("$where: '$name' must hold strings")
    }
}
