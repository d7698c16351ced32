// drivebench-cli nm17x URI settings NODE: input and key modes, scaling from the pitch, jump
// filter and dynamic pre-shutdown of one display, by SDO.
#include "nm17xargs.h"

#include "core/printable.h"
#include "devices/nm17x/nm17xline.h"

namespace db::cli {

namespace {
using namespace db::nm17x;
using namespace nm17xargs;
} // namespace

// A mode name or its number: "takten" or "1" (names as in `modes`, case-insensitive).
static std::optional<int> modeArg(const QString &text, const QStringList &modes)
{
    bool ok = false;
    const int n = text.toInt(&ok);
    if (ok)
        return (n >= 0 && n < modes.size()) ? std::optional(n) : std::nullopt;
    const qsizetype i = modes.indexOf(text.toLower());
    return i >= 0 ? std::optional(int(i)) : std::nullopt;
}

// The operating modes and settings of one display by SDO: the writes asked for by options, then
// every setting as the display has it.
int nm17xSettings(Context &c, Nm17xLine &line)
{
    if (c.args.size() != 3)
        return fail(c,
                    usage(Tr::tr("usage: nm17x URI settings NODE [--input-mode M] [--key-mode M] "
                                 "[--pitch MM [--steps N]] [--filter-width STEPS] "
                                 "[--filter-count N] [--pre-shutdown on|off]")));
    const auto node = nodeArg(c.args.at(2));
    if (!node)
        return fail(c, node.error());
    const auto state = Reply::wait(line.readState(*node));
    if (!state)
        return fail(c, state.error());
    const Variant variant = state->value<DisplayState>().variant;
    const auto option = [&c](const char *name) {
        const QString key = QLatin1String(name);
        return c.parser->isSet(key) ? std::optional(c.parser->value(key)) : std::nullopt;
    };
    QList<std::pair<ObjectAddress, qint64>> writes;
    if (const auto m = option("input-mode")) {
        const auto mode = modeArg(*m,
                                  { QStringLiteral("standard"), QStringLiteral("takten"),
                                    QStringLiteral("externposi"), QStringLiteral("off") });
        if (!mode)
            return fail(c, usage(Tr::tr("--input-mode takes standard, takten, externposi or off")));
        writes.append({ { 0x2041, 3 }, *mode });
    }
    if (const auto m = option("key-mode")) {
        const auto mode = modeArg(*m,
                                  { QStringLiteral("standard"), QStringLiteral("slow"),
                                    QStringLiteral("middle"), QStringLiteral("fast") });
        if (!mode)
            return fail(c, usage(Tr::tr("--key-mode takes standard, slow, middle or fast")));
        writes.append({ { 0x2041, 4 }, *mode });
    }
    const auto steps =
        intOption(c, QStringLiteral("steps"), stepsPerRevolution(variant), 1, 1 << 24);
    if (!steps)
        return fail(c, steps.error());
    if (const auto p = option("pitch")) {
        const auto pitch = parseMillimetres(*p);
        if (!pitch || *pitch <= 0)
            return fail(c, usage(Tr::tr("--pitch takes the spindle pitch in mm per revolution")));
        writes.append({ { 0x2004, 0 }, scalingFor(*pitch, *steps) });
    }
    for (const auto &[name, sub] : { std::pair("filter-width", 1), std::pair("filter-count", 2) }) {
        if (const auto v = option(name)) {
            bool ok = false;
            const qint64 n = v->toLongLong(&ok);
            if (!ok)
                return fail(c, usage(Tr::tr("--%1 takes a number").arg(QLatin1String(name))));
            writes.append({ { 0x2005, quint8(sub) }, n });
        }
    }
    if (const auto v = option("pre-shutdown")) {
        if (*v != u"on" && *v != u"off")
            return fail(c, usage(Tr::tr("--pre-shutdown takes on or off")));
        writes.append({ { 0x2041, 2 }, *v == u"on" ? 1 : 0 });
    }
    for (const auto &[address, value] : std::as_const(writes)) {
        if (auto written = Reply::wait(line.write(*node, address, value)); !written)
            return fail(c, written.error());
    }
    const ObjectDictionary objects = dictionary(variant, *node);
    QList<ObjectAddress> shown = { { 0x2004, 0 }, { 0x2005, 1 }, { 0x2005, 2 } };
    if (hasMotor(variant))
        shown.append({ { 0x2041, 3 }, { 0x2041, 4 }, { 0x2041, 2 }, { 0x2042, 3 } });
    c.out << Tr::tr("node %1  %2").arg(*node).arg(variantName(variant)) << Qt::endl;
    for (const ObjectAddress address : std::as_const(shown)) {
        const auto read = Reply::wait(line.read(*node, address));
        if (!read)
            return fail(c, read.error());
        const ObjectDef *def = objects.find(address);
        const qint64 v = read->toLongLong();
        const QString text = address == ObjectAddress(0x2004, 0)
            ? Tr::tr("%1 = %2 mm/rev at %3 steps/rev")
                  .arg(v)
                  .arg(pitchOf(quint32(v), *steps) / 100.0, 0, 'f', 2)
                  .arg(*steps)
            : def->localDisplayText(def->type == DataType::Integer32 ? QVariant(qlonglong(v))
                                                                     : QVariant(qulonglong(v)));
        c.out << QStringLiteral("  %1 %2: %3").arg(address.toString(), def->name, text) << Qt::endl;
    }
    return ExitOk;
}

} // namespace db::cli
