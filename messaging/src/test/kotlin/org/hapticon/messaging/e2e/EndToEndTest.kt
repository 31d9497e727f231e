package org.hapticon.messaging.e2e

import org.hapticon.testing.TestKeyPins
import com.google.crypto.tink.Aead
import com.google.crypto.tink.KeysetHandle
import com.google.crypto.tink.RegistryConfiguration
import com.google.crypto.tink.TinkProtoKeysetFormat
import com.google.crypto.tink.aead.AeadConfig
import com.google.crypto.tink.aead.PredefinedAeadParameters
import com.google.crypto.tink.hybrid.PredefinedHybridParameters
import com.google.crypto.tink.signature.PredefinedSignatureParameters
import org.hapticon.messaging.RejectionReason
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.ByteArrayOutputStream
import java.io.DataOutputStream
import java.io.File
import java.nio.file.Files
import java.security.GeneralSecurityException
import java.util.Base64

class EndToEndTest {
    @get:Rule
    val temp = TemporaryFolder()

    private val aliceKeys = Identity.generate("alice")
    private val bobKeys = Identity.generate("bob")
    private val alice = EndToEnd(aliceKeys, TestKeyPins().apply { pin(bobKeys.bundle) })
    private val bob = EndToEnd(bobKeys, TestKeyPins())
    private val text = "{\"schema\":\"hapticon.message\",\"text\":\"meet at 5\"}".toByteArray()

    private fun refusal(opened: Opened): Opened.Refused = opened as? Opened.Refused ?: throw AssertionError("expected a refusal")

    private fun fields(sealed: ByteArray): MutableMap<String, String> =
        Regex("\"(keys|ct|sig)\":\"([^\"]+)\"").findAll(String(sealed)).associate { it.groupValues[1] to it.groupValues[2] }.toMutableMap()

    private fun reassemble(fields: Map<String, String>): ByteArray =
        "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\"${fields["keys"]}\",\"ct\":\"${fields["ct"]}\",\"sig\":\"${fields["sig"]}\"}".toByteArray()

    @Test
    fun seal_thenOpenByTheRecipient_givesThePlaintextAndPinsTheSender() {
        val sealed = alice.seal("bob", text)
        assertFalse("the plaintext must not be visible", String(sealed).contains("meet at 5"))
        assertTrue(EndToEnd.looksSealed(sealed))
        assertNull(bob.safetyNumber("alice"))
        assertFalse(bob.hasKeyOf("alice"))
        assertArrayEquals(text, (bob.open("alice", sealed) as Opened.Plain).plaintext)
        assertEquals(alice.safetyNumber("bob"), bob.safetyNumber("alice")) // pinned on first contact, both see one number
        assertTrue(bob.hasKeyOf("alice"))
        assertFalse(bob.hasKeyOf("carol"))
    }

    @Test
    fun seal_twice_givesDifferentCiphertexts() {
        // A fresh HPKE encapsulation each time: equal messages are not recognisable on the wire.
        assertNotEquals(fields(alice.seal("bob", text))["ct"], fields(alice.seal("bob", text))["ct"])
    }

    @Test
    fun seal_recipientWithoutKnownKey_throwsNamingTheRecipient() {
        try {
            alice.seal("carol", text)
            fail("sealed without a key")
        } catch (e: E2eException) {
            assertEquals("no key of carol yet: carol has not published one (an old client, or never connected with end-to-end encryption)", e.message)
        }
    }

    @Test
    fun open_alteredCiphertextOrSignature_isRefusedAsForged() {
        val sealed = fields(alice.seal("bob", text))
        val ct = Base64.getDecoder().decode(sealed["ct"]).also { it[it.size - 1] = (it[it.size - 1] + 1).toByte() }
        val altered = reassemble(sealed + ("ct" to Base64.getEncoder().encodeToString(ct)))
        assertEquals(
            Opened.Refused(RejectionReason.FORGED, "signature of alice does not verify: forged or altered on the way"),
            bob.open("alice", altered),
        )
        assertEquals(RejectionReason.FORGED, refusal(bob.open("alice", reassemble(sealed + ("sig" to "AAAA")))).reason)
    }

    @Test
    fun open_signedByAnotherKeyWithAlicesPinnedKeysInside_isRefusedAsForged() {
        bob.open("alice", alice.seal("bob", text)) // pins alice
        // The operator re-signs a payload of its own with its key, but keeps alice's keys in it.
        val mallory = EndToEnd(Identity.generate("alice"), TestKeyPins().apply { pin(bobKeys.bundle) })
        val forged = fields(mallory.seal("bob", "forged".toByteArray()))
        forged["keys"] = fields(alice.seal("bob", text))["keys"]!!
        assertEquals(RejectionReason.FORGED, refusal(bob.open("alice", reassemble(forged))).reason)
    }

    @Test
    fun open_payloadForBobReplayedIntoCarolsInbox_isRefused() {
        val carolKeys = Identity.generate("carol")
        val carol = EndToEnd(carolKeys, TestKeyPins())
        // Signed for alice→bob: carol's check of alice→carol fails (the recipient is in the signed bytes).
        assertEquals(RejectionReason.FORGED, refusal(carol.open("alice", alice.seal("bob", text))).reason)
    }

    @Test
    fun open_keysOfAnotherUserThanTheTopicSender_isRefused() {
        assertEquals(
            Opened.Refused(RejectionReason.FORGED, "sealed payload on the topic of mallory carries the keys of alice"),
            bob.open("mallory", alice.seal("bob", text)),
        )
    }

    @Test
    fun open_newKeyAfterFirstContact_isHeldBackUntilTrusted() {
        bob.open("alice", alice.seal("bob", text))
        val before = bob.safetyNumber("alice")!!
        val newAlice = EndToEnd(Identity.generate("alice"), TestKeyPins().apply { pin(bobKeys.bundle) })
        val sealed = newAlice.seal("bob", text)
        val refused = refusal(bob.open("alice", sealed))
        assertEquals(RejectionReason.KEY_CHANGED, refused.reason)
        val after = SafetyNumber.of(bobKeys.bundle, newAlice.identity.bundle)
        assertEquals("alice's key changed (safety number now $after, was $before); message held back until you trust the new key", refused.detail)
        assertEquals(before, bob.safetyNumber("alice")) // the pin stays
        assertEquals(newAlice.identity.bundle, bob.trust("alice"))
        assertArrayEquals(text, (bob.open("alice", sealed) as Opened.Plain).plaintext) // the sender's resend now opens
        assertNull(bob.trust("alice"))
    }

    @Test
    fun open_sealedForAnOldKeyOfTheRecipient_isUndecryptable() {
        val sealed = alice.seal("bob", text)
        val newBob = EndToEnd(Identity.generate("bob"), TestKeyPins())
        assertEquals(RejectionReason.UNDECRYPTABLE, refusal(newBob.open("alice", sealed)).reason)
    }

    @Test
    fun open_plaintextOrBrokenSealedForm_isRefusedWithItsReason() {
        assertEquals(RejectionReason.NOT_ENCRYPTED, refusal(bob.open("alice", text)).reason)
        assertEquals(RejectionReason.MALFORMED_JSON, refusal(bob.open("alice", "{\"schema\":\"hapticon.sealed\",\"version\":2}".toByteArray())).reason)
        assertEquals(RejectionReason.MALFORMED_JSON, refusal(bob.open("alice", reassemble(mapOf("keys" to "!!", "ct" to "AA==", "sig" to "AA==")))).reason)
        assertEquals(RejectionReason.NOT_ENCRYPTED, refusal(bob.open("alice", ByteArray(0))).reason)
        // A huge base64 run costs linear time and is refused, not parsed into keys.
        val huge = reassemble(mapOf("keys" to "A".repeat(60_000), "ct" to "AA==", "sig" to "AA=="))
        assertEquals(RejectionReason.FORGED, refusal(bob.open("alice", huge)).reason)
    }

    @Test
    fun open_payloadRecordedFromTheStringTemplateWriter_opensAndIsWrittenAgainByteForByte() {
        // Sealed by alice for bob with the string template that wrote every sealed payload before SealedDocument,
        // bob's keys saved beside it: old payloads must still open, and the document must write the same bytes.
        val recordedBob = EndToEnd(Identity.deserialize("bob", Base64.getDecoder().decode(RECORDED_BOB_KEYS), null), TestKeyPins())
        val recorded = RECORDED_SEALED.toByteArray(Charsets.US_ASCII)
        assertArrayEquals(text, (recordedBob.open("alice", recorded) as Opened.Plain).plaintext)
        val parts = SealedPayload.decode(recorded)!!
        assertArrayEquals(recorded, SealedPayload(parts.keys, parts.ciphertext, parts.signature).encode())
    }

    @Test
    fun seal_writesTheOneCompactFormInSchemaOrder() {
        val sealed = alice.seal("bob", text)
        val f = fields(sealed)
        assertEquals(String(reassemble(f)), String(sealed, Charsets.US_ASCII))
    }

    @Test
    fun open_sealedFormBrokenInAnyWay_isTheOneMalformedRefusal() {
        val f = fields(alice.seal("bob", text))
        val keys = f.getValue("keys")
        val ct = f.getValue("ct")
        val sig = f.getValue("sig")
        for (broken in listOf(
            "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\"$keys\",\"keys\":\"$keys\",\"ct\":\"$ct\",\"sig\":\"$sig\"}", // duplicate member
            "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\"$keys\",\"ct\":\"\",\"sig\":\"$sig\"}", // empty ciphertext
            "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\"$keys\",\"ct\":\"$ct\"}", // no signature
            "{\"schema\":\"hapticon.sealed\",\"version\":\"1\",\"keys\":\"$keys\",\"ct\":\"$ct\",\"sig\":\"$sig\"}", // version as text
            "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":[\"$keys\"],\"ct\":\"$ct\",\"sig\":\"$sig\"}", // keys in an array
            "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\"$keys\",\"ct\":\"$ct\",\"sig\":\"$sig\"", // cut short
        )) {
            val refused = refusal(bob.open("alice", broken.toByteArray()))
            assertEquals(broken, Opened.Refused(RejectionReason.MALFORMED_JSON, "sealed payload from alice is not in the sealed form"), refused)
        }
    }

    @Test
    fun learn_firstUnchangedChangedAndForeignKeys() {
        assertEquals(KeyNews.Pinned(aliceKeys.bundle), bob.learn("alice", aliceKeys.bundle.encoded))
        assertEquals(KeyNews.Unchanged, bob.learn("alice", aliceKeys.bundle.encoded))
        val newKeys = Identity.generate("alice").bundle
        val changed = bob.learn("alice", newKeys.encoded) as KeyNews.Changed
        assertEquals(newKeys, changed.bundle)
        assertEquals(SafetyNumber.of(bobKeys.bundle, aliceKeys.bundle), changed.pinnedSafetyNumber)
        assertEquals(newKeys, bob.changedKey("alice"))
        assertEquals(KeyNews.Invalid("the key topic of mallory holds the keys of alice"), bob.learn("mallory", aliceKeys.bundle.encoded))
        assertTrue(bob.learn("alice", byteArrayOf(1, 0)) is KeyNews.Invalid)
    }

    @Test
    fun keyBundle_otherAlgorithms_areRefused() {
        // An ECIES-P256 key where HPKE-X25519 belongs: nobody may downgrade a conversation.
        val ecies = KeysetHandle.generateNew(PredefinedHybridParameters.ECIES_P256_HKDF_HMAC_SHA256_AES128_GCM).publicKeysetHandle
        val ed = KeysetHandle.generateNew(PredefinedSignatureParameters.ED25519).publicKeysetHandle
        val encoded = bundleBytes("mallory", TinkProtoKeysetFormat.serializeKeysetWithoutSecret(ecies), TinkProtoKeysetFormat.serializeKeysetWithoutSecret(ed))
        try {
            KeyBundle.decode(encoded)
            fail("accepted ECIES")
        } catch (e: GeneralSecurityException) {
            assertEquals("the encryption key of mallory is not HPKE X25519/HKDF-SHA256/AES-128-GCM", e.message)
        }
        assertEquals(aliceKeys.bundle, KeyBundle.decode(aliceKeys.bundle.encoded))
    }

    @Test
    fun safetyNumber_sameForBothSides_sixtyDigits_changesWithEitherKey() {
        val number = SafetyNumber.of(aliceKeys.bundle, bobKeys.bundle)
        assertEquals(number, SafetyNumber.of(bobKeys.bundle, aliceKeys.bundle))
        assertTrue(number, Regex("(\\d{5} ){11}\\d{5}").matches(number))
        assertNotEquals(number, SafetyNumber.of(aliceKeys.bundle, Identity.generate("bob").bundle))
    }

    @Test
    fun identity_serializedClearOrWrapped_readsBackTheSameKeys() {
        AeadConfig.register()
        val wrap = KeysetHandle.generateNew(PredefinedAeadParameters.AES256_GCM).getPrimitive(RegistryConfiguration.get(), Aead::class.java)
        val clear = Identity.deserialize("alice", aliceKeys.serialize(null), null)
        val wrapped = aliceKeys.serialize(wrap)
        assertEquals(aliceKeys.bundle, clear.bundle)
        assertEquals(aliceKeys.bundle, Identity.deserialize("alice", wrapped, wrap).bundle)
        // The reread keys open what was sealed for the original.
        val sealedForAlice = EndToEnd(bobKeys, TestKeyPins().apply { pin(aliceKeys.bundle) }).seal("alice", text)
        assertTrue(EndToEnd(clear, TestKeyPins()).open("bob", sealedForAlice) is Opened.Plain)
        for ((user, key) in listOf("mallory" to wrap, "alice" to null)) {
            try {
                Identity.deserialize(user, wrapped, key) // another user's associated data, or no wrapping key
                fail("read wrapped keys as $user with $key")
            } catch (e: GeneralSecurityException) {
                // expected
            }
        }
    }

    @Test
    fun loadOrCreate_writesAPrivateFileOnceAndRereadsIt() {
        val file = File(temp.root, "keys/alice.keys")
        val first = Identity.loadOrCreate("alice", file)
        assertEquals("rw-------", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(file.toPath())))
        assertEquals(first.bundle, Identity.loadOrCreate("alice", file).bundle)
        assertFalse(File(temp.root, "keys/alice.keys.tmp").exists())
    }

    @Test
    fun fileKeyPins_pinAndReread_damagedFileThrows() {
        val pins = FileKeyPins(temp.root)
        assertNull(pins.pinned("alice"))
        pins.pin(aliceKeys.bundle)
        assertEquals(aliceKeys.bundle, FileKeyPins(temp.root).pinned("alice"))
        File(temp.root, "alice.pub").writeBytes(byteArrayOf(1, 0, 5))
        try {
            pins.pinned("alice")
            fail("a damaged pin counted as none")
        } catch (e: IllegalStateException) {
            assertTrue(e.message!!, e.message!!.endsWith("delete it to pin alice's key again"))
        }
    }

    private companion object {
        /** Bob's identity (`Identity.serialize(null)`) when [RECORDED_SEALED] was sealed for him. */
        const val RECORDED_BOB_KEYS: String =
            "AQAAAJ8IopTywgMSlgEKiQEKNXR5cGUuZ29vZ2xlYXBpcy5jb20vZ29vZ2xlLmNyeXB0by50aW5rLkhwa2VQcml2YXRlS2V5Ek4S" +
            "KhIGCAEQARgBGiANN1mak2WW5JbXtWEkpj9fmOIwRim5ZNCza6yFWhFLeRog3+QLhwxZLmghH79HL3kG/9Ql7f0hh1pPX44ZQiVC" +
            "9aMYAhABGKKU8sIDIAEAAACaCKvfysYCEpEBCoQBCjh0eXBlLmdvb2dsZWFwaXMuY29tL2dvb2dsZS5jcnlwdG8udGluay5FZDI1" +
            "NTE5UHJpdmF0ZUtleRJGEiBfW1wUVAQaKSOS2st6xA7tNH4s3bSvAcHC4iUxo+TitRoiEiDdfQ+xevjYeW6m01aFPDw/wqR8KRkx" +
            "AxytFt6KLArWzxgCEAEYq9/KxgIgAQ=="

        /** `alice.seal("bob", text)` as the string template wrote it. */
        const val RECORDED_SEALED: String =
            "{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\"AQAFYWxpY2UAeAi0mK+hAxJwCmQKNHR5cGUuZ29vZ2" +
            "xlYXBpcy5jb20vZ29vZ2xlLmNyeXB0by50aW5rLkhwa2VQdWJsaWNLZXkSKhIGCAEQARgBGiAjAVjsilWfZUIP4cfw" +
            "WWh7aiTijdUJTFT9OcGE3pGEFxgDEAEYtJivoQMgAQBzCPCfpa0DEmsKXwo3dHlwZS5nb29nbGVhcGlzLmNvbS9nb2" +
            "9nbGUuY3J5cHRvLnRpbmsuRWQyNTUxOVB1YmxpY0tleRIiEiDR3OngoJkHQhEa9TldIEtIW89YuJk3X64pXnRx1a1a" +
            "LxgDEAEY8J+lrQMgAQ==\",\"ct\":\"AThciiLDRGARjfvPI+ltehpN1ZXHr6mlAfBMVWqMhhHVuMuWRpWw3aIQtipqw5" +
            "0iCe45lH+D7Sqo9cAWMe7VM6bL0WzOJ7iJTPsdp+00MR0zV74hsOQx/CpH9lK+nBydITFb/jM=\",\"sig\":\"ATWpT/D" +
            "XS7JejCGhwFHyw+aM7kH0kLMu+39JjOowDkaYeKuxU9z4rqzqB0EBlfr/CkpSmlDJ2Pa7QlfjWGVBHVnkqXAK\"}"
    }

    private fun bundleBytes(user: String, encryption: ByteArray, signature: ByteArray): ByteArray = ByteArrayOutputStream().also { bytes ->
        DataOutputStream(bytes).apply {
            writeByte(1)
            for (field in listOf(user.toByteArray(), encryption, signature)) {
                writeShort(field.size)
                write(field)
            }
        }
    }.toByteArray()
}
