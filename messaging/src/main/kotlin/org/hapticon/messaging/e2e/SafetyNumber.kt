package org.hapticon.messaging.e2e

import java.security.MessageDigest

/**
 * The number two people compare (read aloud, or side by side) to know that nobody between them swapped
 * their keys: Signal's "safety number" construction (libsignal `NumericFingerprintGenerator`, version 0):
 * for each side, SHA-512 over `0x0000 ‖ key ‖ user name`, then 5,200 rounds of SHA-512 over `digest ‖ key`;
 * the first 30 bytes become six 5-digit groups (each 5-byte big-endian chunk modulo 100,000); the two
 * 30-digit halves are sorted, so both people see the same 60 digits. Here the key is [KeyBundle.encoded]
 * (both public keys), where Signal uses the identity key alone.
 */
public object SafetyNumber {
    private const val ITERATIONS = 5_200

    /** 60 digits in twelve groups of five, the same for both users whichever calls it. */
    public fun of(a: KeyBundle, b: KeyBundle): String {
        val halves = listOf(half(a), half(b)).sorted()
        return (halves[0] + halves[1]).chunked(5).joinToString(" ")
    }

    private fun half(bundle: KeyBundle): String {
        val sha512 = MessageDigest.getInstance("SHA-512")
        val key = bundle.encoded
        sha512.update(byteArrayOf(0, 0))
        sha512.update(key)
        var digest = sha512.digest(bundle.user.toByteArray(Charsets.UTF_8))
        repeat(ITERATIONS) {
            sha512.update(digest)
            digest = sha512.digest(key)
        }
        return (0 until 6).joinToString("") { chunk ->
            var value = 0L
            for (i in 0 until 5) value = (value shl 8) or (digest[chunk * 5 + i].toLong() and 0xff)
            "%05d".format(value % 100_000)
        }
    }
}
