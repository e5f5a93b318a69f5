// SPDX-License-Identifier: GPL-3.0-or-later
// Text printed on a signed report (core/base/DisplayText.h), issue 31: every control character
// but tab, every bidirectional formatting character and, in one-line text, every line break is
// refused, named by its code point and its position in characters from 1; lengths count code
// points, not bytes. The expected positions and counts are those of the literals here.

#include "core/base/DisplayText.h"

#include <QtTest>

using namespace kinstab;

namespace {

std::string oneLine(std::string_view text, std::size_t max = 200) {
    return displayTextProblem(text, max, TextLines::Single);
}

} // namespace

class TestDisplayText : public QObject {
    Q_OBJECT
private slots:
    void refused_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("RLO") << QByteArray("S 12345\u202E67890")
                             << "contains U+202E (a bidirectional override) at character 8";
        QTest::newRow("LRO") << QByteArray("\u202Dab")
                             << "contains U+202D (a bidirectional override)";
        QTest::newRow("LRE") << QByteArray("a\u202A")
                             << "contains U+202A (a bidirectional embedding)";
        QTest::newRow("RLE") << QByteArray("a\u202B")
                             << "contains U+202B (a bidirectional embedding)";
        QTest::newRow("PDF") << QByteArray("a\u202C")
                             << "contains U+202C (a bidirectional embedding)";
        QTest::newRow("LRI") << QByteArray("a\u2066")
                             << "contains U+2066 (a bidirectional isolate)";
        QTest::newRow("RLI") << QByteArray("a\u2067")
                             << "contains U+2067 (a bidirectional isolate)";
        QTest::newRow("FSI") << QByteArray("a\u2068")
                             << "contains U+2068 (a bidirectional isolate)";
        QTest::newRow("PDI") << QByteArray("a\u2069")
                             << "contains U+2069 (a bidirectional isolate)";
        QTest::newRow("LRM") << QByteArray("a\u200E") << "contains U+200E (a bidirectional mark)";
        QTest::newRow("RLM") << QByteArray("a\u200F") << "contains U+200F (a bidirectional mark)";
        QTest::newRow("ALM") << QByteArray("a\u061C") << "contains U+061C (a bidirectional mark)";
        QTest::newRow("NUL") << QByteArray("ab\0c", 4) << "contains U+0000 (NUL) at character 3";
        QTest::newRow("BEL") << QByteArray("\a")
                             << "contains U+0007 (a control character) at character 1";
        QTest::newRow("ESC") << QByteArray("x\x1b[31m")
                             << "contains U+001B (a control character) at character 2";
        QTest::newRow("unit separator")
            << QByteArray("\x1f") << "contains U+001F (a control character)";
        QTest::newRow("DEL") << QByteArray("\x7f") << "contains U+007F (a control character)";
        QTest::newRow("C1 NEL") << QByteArray("a\u0085") << "contains U+0085 (a control character)";
        QTest::newRow("C1 CSI") << QByteArray("\u009B") << "contains U+009B (a control character)";
        QTest::newRow("LF") << QByteArray("a\nb")
                            << "contains U+000A (a line break in one-line text) at character 2";
        QTest::newRow("CR") << QByteArray("a\r")
                            << "contains U+000D (a line break in one-line text)";
        QTest::newRow("line separator")
            << QByteArray("a\u2028") << "contains U+2028 (a line break in one-line text)";
        QTest::newRow("paragraph separator")
            << QByteArray("a\u2029") << "contains U+2029 (a line break in one-line text)";
        // Characters before the bad one are counted as characters: é and 中 are one each.
        QTest::newRow("position in characters")
            << QByteArray("é中\u202E")
            << "contains U+202E (a bidirectional override) at character 3";
        QTest::newRow("stray byte")
            << QByteArray("ab\xff") << "is not UTF-8 text (a stray byte at character 3)";
        QTest::newRow("surrogate in UTF-8")
            << QByteArray("\xed\xa0\x80") << "is not UTF-8 text (a stray byte at character 1)";
        QTest::newRow("cut sequence") << QByteArray("a\xe4\xb8") << "is not UTF-8 text";
    }
    void refused() {
        QFETCH(QByteArray, text);
        QFETCH(QString, message);
        const std::string e = oneLine(std::string_view(text.constData(), text.size()));
        QVERIFY2(QString::fromStdString(e).startsWith(message), e.c_str());
    }
    void accepted() {
        QCOMPARE(oneLine(""), std::string());
        QCOMPARE(oneLine("Example Structural Engineers\tLos Angeles"), std::string()); // tab
        QCOMPARE(oneLine("Ingeniería Sísmica S.A. — 東京 — Øst"), std::string());
        QCOMPARE(oneLine("מהנדס אחראי"), std::string());         // Hebrew, no marks needed
        QCOMPARE(oneLine("المهندس المسؤول"), std::string());     // Arabic
        QCOMPARE(oneLine("emoji \U0001F3D7 ok"), std::string()); // four UTF-8 bytes
        const std::string lines = "first line\nsecond line\r\nthird\u2028fourth";
        QCOMPARE(displayTextProblem(lines, 200, TextLines::Multiple), std::string());
        // A multi-line text refuses the rest as a one-line text does.
        QVERIFY(!displayTextProblem("a\n\u202E", 200, TextLines::Multiple).empty());
        QVERIFY(!displayTextProblem("a\n\x1b", 200, TextLines::Multiple).empty());
    }
    void lengthInCharacters() {
        std::string e200, e201;
        for (int i = 0; i < 200; ++i)
            e200 += "é"; // 400 bytes, 200 characters
        e201 = e200 + "é";
        QCOMPARE(utf8Chars(e200), std::size_t(200));
        QCOMPARE(utf8Chars("\U0001F3D7"), std::size_t(1));
        QCOMPARE(utf8Chars("a\xff"), std::size_t(2)); // a stray byte counts as one
        QCOMPARE(oneLine(e200), std::string());
        QCOMPARE(oneLine(e201), std::string("201 characters, more than the limit of 200"));
        QCOMPARE(checkDisplayText("info.firm", e201, 200),
                 std::string("info.firm: 201 characters, more than the limit of 200"));
        QCOMPARE(checkDisplayText("info.firm", "ok", 200), std::string());
    }
};

QTEST_APPLESS_MAIN(TestDisplayText)
#include "tst_display_text.moc"
