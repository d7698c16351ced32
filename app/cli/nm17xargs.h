#pragma once

// Argument helpers shared by the nm17x commands (commands_nm17x*.cpp).

#include "commands.h"

#include "canopen/canopenids.h"

#include <QCoreApplication>

namespace db::nm17x {
class Nm17xLine;
}

namespace db::cli {

namespace nm17xargs {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};

inline Error usage(const QString &text)
{
    return Error(Error::Kind::InvalidArgument, text);
}

inline Result<canopen::NodeId> nodeArg(const QString &text)
{
    bool ok = false;
    const uint node = text.toUInt(&ok);
    if (!ok || node < 1 || node > 127)
        return usage(Tr::tr("'%1' is not a node id 1..127").arg(text));
    return canopen::NodeId(node);
}

inline Result<int> intOption(const Context &c, const QString &name, int fallback, int min, int max)
{
    if (!c.parser->isSet(name))
        return fallback;
    bool ok = false;
    const int v = c.parser->value(name).toInt(&ok);
    if (!ok || v < min || v > max)
        return usage(Tr::tr("--%1 takes a number %2..%3").arg(name).arg(min).arg(max));
    return v;
}

} // namespace nm17xargs

// nm17x URI settings NODE [options]: the display's modes and settings by SDO.
int nm17xSettings(Context &c, nm17x::Nm17xLine &line);

} // namespace db::cli
