#pragma once

#include <QChar>
#include <QString>

#include <array>

namespace db::morse {

// One brightness reading: time in seconds (strictly increasing), brightness on any scale
// (camera grey level, photodiode volts, ...). The decoder only uses differences and ratios.
struct Sample
{
    double t = 0.0;
    double value = 0.0;
};

// A stretch of constant LED state found by the level slicer.
struct Interval
{
    bool on = false;
    double start = 0.0; // seconds
    double duration = 0.0; // seconds
    bool truncated = false; // began before the decoder saw the LED: true length unknown
    // Standard deviation of the start time from noise on the samples around the threshold
    // crossing (seconds; 0 on a clean signal and for a truncated start).
    double startSigma = 0.0;
};

enum class ElementKind {
    Dit, // mark of 1 unit
    Dah, // mark of 3 units
    LongMark, // mark far longer than a dah: not Morse (LED steady on, glitch of the slicer)
    IntraGap, // 1 unit between the elements of a character
    LetterGap, // 3 units between characters
    WordGap, // 7 units or more: between words and between repetitions of the message
};

// One classified element of the timeline.
struct Element
{
    ElementKind kind = ElementKind::Dit;
    double start = 0.0; // seconds
    double duration = 0.0; // seconds
    double units = 0.0; // duration in units, corrected for the duty offset
    double edgeSigma = 0.0; // units: uncertainty of the length from noise at its two edges
};

// One decoded character; ch is '?' when the code is unknown or the character began before
// the recording, ' ' for a word gap.
struct DecodedChar
{
    QChar ch;
    QString code; // ".-.-." ; empty for ' '
    double start = 0.0;
    double end = 0.0;
};

// Why a decoder has no (confident) IP address.
enum class Reason {
    None, // a confident IP address was decoded
    InvalidInput, // no usable samples (empty, not finite, time not increasing)
    NoModulation, // brightness never shows two distinct levels: LED not found or not blinking
    NotMorse, // the LED blinks, but its timing does not fit Morse at 40-500 ms per unit
    TooShort, // Morse found, but not one complete message yet
    NoValidIp, // complete messages, but none carries "IP" and four octets 0..255
    LowConfidence, // an IP address, but the repetitions do not yet agree enough
};

QString reasonText(Reason reason);

// An IP address voted from all observations so far.
struct IpEstimate
{
    std::array<int, 4> octets { -1, -1, -1, -1 }; // -1: octet not seen yet
    double confidence = 0.0; // 0..1, see IpVoter
    int messages = 0; // complete "IPa+b+c+d:" readings that read octets (IpVoter::kTie)
    bool complete() const
    {
        return octets[0] >= 0 && octets[1] >= 0 && octets[2] >= 0 && octets[3] >= 0;
    }
    bool anyOctet() const
    {
        return octets[0] >= 0 || octets[1] >= 0 || octets[2] >= 0 || octets[3] >= 0;
    }
    QString toString() const; // "192.168.2.150", '?' for unknown octets
};

} // namespace db::morse
