package org.hapticon.companion

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.MODEL_CHOICES
import org.hapticon.companion.cli.UsageException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class ArgumentsTest {
    private fun parse(vararg args: String) =
        Arguments.parse("render", args.toList(), valueOptions = setOf("rate", "out", "model"), flagOptions = setOf("json"))

    private fun usageError(block: () -> Unit): String {
        try {
            block()
        } catch (e: UsageException) {
            return e.message!!
        }
        fail("expected a UsageException")
        throw AssertionError()
    }

    @Test
    fun parse_spaceAndEqualsForms_giveTheSameValues() {
        val spaced = parse("stroke", "--rate", "8000", "--out", "a.wav")
        val joined = parse("--rate=8000", "stroke", "--out=a.wav")
        for (arguments in listOf(spaced, joined)) {
            assertEquals(listOf("stroke"), arguments.positionals)
            assertEquals(8000, arguments.int("rate", 44_100))
            assertEquals("a.wav", arguments.required("out"))
        }
    }

    @Test
    fun parse_flagPresentOrAbsent_isReported() {
        assertTrue(parse("--json").flag("json"))
        assertFalse(parse().flag("json"))
    }

    @Test
    fun int_absent_isTheDefault() {
        assertEquals(44_100, parse().int("rate", 44_100))
    }

    @Test
    fun int_notANumber_namesOptionAndValue() {
        assertEquals("--rate must be a whole number, got '44.1k'", usageError { parse("--rate", "44.1k").int("rate", 0) })
    }

    @Test
    fun parse_unknownLongOrShortOption_isRejected() {
        assertEquals("unknown option --loud for render", usageError { parse("--loud") })
        assertEquals("unknown option -r for render", usageError { parse("-r", "8000") })
    }

    @Test
    fun parse_valueMissingAtEndOrBeforeAnotherOption_isRejected() {
        assertEquals("--out needs a value", usageError { parse("stroke", "--out") })
        assertEquals("--out needs a value", usageError { parse("--out", "--rate", "8000") })
        assertEquals("--out needs a value", usageError { parse("--out=") })
    }

    @Test
    fun parse_optionGivenTwice_isRejected() {
        assertEquals("--rate given twice", usageError { parse("--rate", "8000", "--rate", "9000") })
        assertEquals("--json given twice", usageError { parse("--json", "--json") })
    }

    @Test
    fun parse_flagWithValue_isRejected() {
        assertEquals("--json takes no value", usageError { parse("--json=yes") })
    }

    @Test
    fun parse_negativeNumberAfterValueOption_isTheValue() {
        assertEquals(-5, parse("--rate", "-5").int("rate", 0))
    }

    @Test
    fun choice_isCaseInsensitiveAndListsTheChoicesWhenWrong() {
        assertEquals(org.hapticon.core.render.EnvelopeModel.PROCESSING, parse("--model", "Processing").choice("model", MODEL_CHOICES, org.hapticon.core.render.EnvelopeModel.PAPER))
        assertEquals(
            "--model must be paper or processing, got 'jsyn'",
            usageError { parse("--model", "jsyn").choice("model", MODEL_CHOICES, org.hapticon.core.render.EnvelopeModel.PAPER) },
        )
    }

    @Test
    fun single_missingOrExtraPositional_isRejected() {
        assertEquals("render needs an ICON", usageError { parse().single("an ICON") })
        assertEquals("unexpected argument 'hit' for render", usageError { parse("stroke", "hit").single("an ICON") })
    }

    @Test
    fun required_absent_namesCommandAndOption() {
        assertEquals("render needs --out", usageError { parse("stroke").required("out") })
    }
}
