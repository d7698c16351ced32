#include "morsecode.h"

#include <array>
#include <cmath>
#include <cstring>

namespace db::morse {
namespace {

struct Entry
{
    char ch;
    const char *code;
};

// ITU-R M.1677-1, section 1.1.
constexpr std::array kTable {
    Entry { 'A', ".-" },     Entry { 'B', "-..." },    Entry { 'C', "-.-." },
    Entry { 'D', "-.." },    Entry { 'E', "." },       Entry { 'F', "..-." },
    Entry { 'G', "--." },    Entry { 'H', "...." },    Entry { 'I', ".." },
    Entry { 'J', ".---" },   Entry { 'K', "-.-" },     Entry { 'L', ".-.." },
    Entry { 'M', "--" },     Entry { 'N', "-." },      Entry { 'O', "---" },
    Entry { 'P', ".--." },   Entry { 'Q', "--.-" },    Entry { 'R', ".-." },
    Entry { 'S', "..." },    Entry { 'T', "-" },       Entry { 'U', "..-" },
    Entry { 'V', "...-" },   Entry { 'W', ".--" },     Entry { 'X', "-..-" },
    Entry { 'Y', "-.--" },   Entry { 'Z', "--.." },    Entry { '0', "-----" },
    Entry { '1', ".----" },  Entry { '2', "..---" },   Entry { '3', "...--" },
    Entry { '4', "....-" },  Entry { '5', "....." },   Entry { '6', "-...." },
    Entry { '7', "--..." },  Entry { '8', "---.." },   Entry { '9', "----." },
    Entry { '.', ".-.-.-" }, Entry { ',', "--..--" },  Entry { ':', "---..." },
    Entry { '?', "..--.." }, Entry { '\'', ".----." }, Entry { '-', "-....-" },
    Entry { '/', "-..-." },  Entry { '(', "-.--." },   Entry { ')', "-.--.-" },
    Entry { '"', ".-..-." }, Entry { '=', "-...-" },   Entry { '+', ".-.-." },
    Entry { '@', ".--.-." },
};

} // namespace

QString codeFor(QChar c)
{
    const QChar upper = c.toUpper();
    for (const Entry &e : kTable) {
        if (upper == QLatin1Char(e.ch))
            return QString::fromLatin1(e.code);
    }
    return {};
}

QChar charFor(QStringView code)
{
    for (const Entry &e : kTable) {
        if (code == QLatin1String(e.code))
            return QLatin1Char(e.ch);
    }
    return {};
}

QChar nearestChar(const std::vector<double> &markUnits, double maxExtraCost)
{
    auto cost = [](double u, double k) {
        const double e = std::log(std::max(u, 1e-3) / k);
        return e * e;
    };
    double hard = 0.0;
    for (double u : markUnits)
        hard += std::min(cost(u, 1.0), cost(u, 3.0));
    QChar best;
    double bestCost = hard + maxExtraCost;
    for (const Entry &e : kTable) {
        if (std::strlen(e.code) != markUnits.size())
            continue;
        double c = 0.0;
        for (std::size_t i = 0; i < markUnits.size(); ++i)
            c += cost(markUnits[i], e.code[i] == '-' ? 3.0 : 1.0);
        if (c <= bestCost) {
            bestCost = c;
            best = QLatin1Char(e.ch);
        }
    }
    return best;
}

std::vector<double> messageElements(const QString &text, double lastGap)
{
    std::vector<double> units;
    for (QChar c : text) {
        if (c == QLatin1Char(' ')) {
            if (!units.empty())
                units.back() = 7.0;
            continue;
        }
        const QString code = codeFor(c);
        for (QChar e : code) {
            units.push_back(e == QLatin1Char('-') ? 3.0 : 1.0);
            units.push_back(1.0);
        }
        if (!code.isEmpty())
            units.back() = 3.0;
    }
    if (!units.empty())
        units.back() = lastGap;
    return units;
}

} // namespace db::morse
