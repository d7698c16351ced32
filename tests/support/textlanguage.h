#pragma once
// Lets a test choose the language device texts are shown in (db::textLanguage()) without a
// compiled translation: while it lives, a translator that knows only the language's own code is
// installed on the application.

#include <QCoreApplication>
#include <QTranslator>

namespace db::test {

class TextLanguage : public QTranslator
{
public:
    explicit TextLanguage(const QString &language)
        : m_language(language)
    {
        QCoreApplication::installTranslator(this);
    }
    ~TextLanguage() override { QCoreApplication::removeTranslator(this); }

    bool isEmpty() const override { return false; }
    QString translate(const char *context, const char *sourceText, const char *, int) const override
    {
        if (qstrcmp(context, "db::TextLanguage") == 0 && qstrcmp(sourceText, "en") == 0)
            return m_language;
        return {};
    }

private:
    QString m_language;
};

} // namespace db::test
