#pragma once
// Trigger settings (value type) and the pure detector that evaluates them sample by sample.
#include "core/addressformat.h"
#include "core/result.h"
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>

namespace db::scope {

// When a Single/Normal capture fires, on which channel, and the window kept around it.
//
// Kinds (levels compare the DISPLAYED value raw*scale+offset; bits test the raw integer):
// - RisingEdge:  previous < level and current >= level (needs a crossing after arming).
// - FallingEdge: previous > level and current <= level (needs a crossing after arming).
// - LevelAbove / LevelBelow: current > level / current < level.
// - WindowInside: level <= current <= level2; WindowOutside: current < level or > level2.
// - BitSet / BitClear: bit `bit` of the raw value is 1 / 0 (e.g. fault = bit 3 of 6041h).
// Edges need two samples after arming; the other kinds are states and also fire on the first
// sample after arming when the condition already holds.
// The trigger time is the time of the sample that fulfils the condition.
struct Trigger
{
    Q_GADGET
public:
    enum class Kind {
        RisingEdge,
        FallingEdge,
        LevelAbove,
        LevelBelow,
        WindowInside,
        WindowOutside,
        BitSet,
        BitClear,
    };
    Q_ENUM(Kind)

    int channel = -1; // recorder channel index; -1 = no trigger
    Kind kind = Kind::RisingEdge;
    double level = 0; // edges, levels, window low bound
    double level2 = 0; // window high bound
    int bit = 0; // BitSet/BitClear, 0..63
    double preTriggerS = 0; // time kept before the trigger
    double postTriggerS = 1; // time recorded after the trigger

    bool isValid() const { return channel >= 0; }

    // Text form of kind/levels/bit without the channel: "rising,100", "inside,0,1000",
    // "bit3,set" (see parse()).
    QString conditionText() const;
    static QString kindName(Kind kind); // "rising", "falling", "above", "below", "inside", ...

    // Parses the CLI/CSV SPEC "CHANNEL,CONDITION":
    //   6064:0,rising,100   6064:0,falling,-5.5   6078:0,above,500   6078:0,below,-500
    //   6064:0,inside,0,1000   6064:0,outside,-10,10   6041:0,bit3,set   6041:0,bit3,clear
    // CHANNEL is a channel id from `channelIds`, as written there or as another spelling of
    // the same address in `format` (so "6041:00" and "6041" find "6041:0"; with the parameter
    // format "372.2" finds "372:2"). pre/post are not part of the spec and stay as in `base`.
    // InvalidArgument naming the problem when the spec is malformed or the channel unknown.
    static Result<Trigger> parse(const QString &spec, const QStringList &channelIds);
    static Result<Trigger> parse(const QString &spec, const QStringList &channelIds,
                                 const Trigger &base,
                                 const AddressFormat &format = AddressFormat::canopen());

    friend bool operator==(const Trigger &, const Trigger &) = default;
};

// Evaluates a Trigger on one channel's successive samples. Pure and cheap (one compare per
// sample); reset() re-arms it (forgets the previous sample).
class TriggerDetector
{
public:
    explicit TriggerDetector(const Trigger &trigger = {}, double scale = 1, double offset = 0);
    void reset() { m_hasPrevious = false; }
    // True when the sample (raw value) fulfils the trigger condition.
    bool feed(double raw);

private:
    bool condition(double raw, double shown) const;

    Trigger m_trigger;
    double m_scale;
    double m_offset;
    double m_previous = 0;
    bool m_hasPrevious = false;
};

} // namespace db::scope

Q_DECLARE_METATYPE(db::scope::Trigger)
