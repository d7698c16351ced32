#pragma once
// Whether a text meant to be German reads as an English sentence: two or more English function
// words and no German one ("connect to the drive" but not "Antrieb an der Achse", not "RefGo
// TPSR"). Catches texts that never went through tr().

#include <QRegularExpression>
#include <QSet>
#include <QString>

namespace db::test {

inline bool readsAsEnglish(const QString &text)
{
    static const QSet<QString> english = {
        QStringLiteral("the"),  QStringLiteral("and"),   QStringLiteral("of"),
        QStringLiteral("to"),   QStringLiteral("is"),    QStringLiteral("are"),
        QStringLiteral("not"),  QStringLiteral("with"),  QStringLiteral("from"),
        QStringLiteral("for"),  QStringLiteral("this"),  QStringLiteral("that"),
        QStringLiteral("no"),   QStringLiteral("on"),    QStringLiteral("at"),
        QStringLiteral("by"),   QStringLiteral("be"),    QStringLiteral("it"),
        QStringLiteral("or"),   QStringLiteral("its"),   QStringLiteral("yet"),
        QStringLiteral("when"), QStringLiteral("has"),   QStringLiteral("have"),
        QStringLiteral("was"),  QStringLiteral("were"),  QStringLiteral("will"),
        QStringLiteral("give"), QStringLiteral("takes"), QStringLiteral("needs"),
    };
    static const QSet<QString> german = {
        QStringLiteral("der"),     QStringLiteral("die"),      QStringLiteral("das"),
        QStringLiteral("und"),     QStringLiteral("ist"),      QStringLiteral("nicht"),
        QStringLiteral("mit"),     QStringLiteral("von"),      QStringLiteral("für"),
        QStringLiteral("ein"),     QStringLiteral("eine"),     QStringLiteral("zu"),
        QStringLiteral("im"),      QStringLiteral("den"),      QStringLiteral("dem"),
        QStringLiteral("des"),     QStringLiteral("auf"),      QStringLiteral("oder"),
        QStringLiteral("bei"),     QStringLiteral("kein"),     QStringLiteral("keine"),
        QStringLiteral("wird"),    QStringLiteral("werden"),   QStringLiteral("sind"),
        QStringLiteral("noch"),    QStringLiteral("aus"),      QStringLiteral("über"),
        QStringLiteral("einer"),   QStringLiteral("eines"),    QStringLiteral("nach"),
        QStringLiteral("braucht"), QStringLiteral("erwartet"), QStringLiteral("nimmt"),
        QStringLiteral("angeben"), QStringLiteral("z"),        QStringLiteral("als"),
    };
    static const QRegularExpression word(QStringLiteral("[A-Za-zÄÖÜäöüß]+"));
    int en = 0;
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const QString w = it.next().captured().toLower();
        if (german.contains(w))
            return false;
        en += english.contains(w) ? 1 : 0;
    }
    return en >= 2;
}

} // namespace db::test
