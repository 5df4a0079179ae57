// WaveformView: zoom about the mouse keeps the time under it, scrolling stays inside the
// sequence, clicks report the time under the mouse, and the words tier is drawn.
#include "timeline/WaveformView.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;

class TestWaveformView : public QObject
{
    Q_OBJECT
private slots:
    void zoomScrollAndClick()
    {
        WaveformView view;
        view.resize(600, 200);
        std::vector<float> samples(48000);
        for (std::size_t i = 0; i < samples.size(); ++i)
            samples[i] = float(0.5 * std::sin(i * 0.05));
        view.setPeaks(std::make_shared<WaveformPeaks>(std::move(samples), 16000));
        view.setWords(Tier{"words", {{0.0, 1.0, "sil"}, {1.0, 2.0, "hello"}, {2.0, 3.0, "world"}}});
        view.setDuration(3.0);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QCOMPARE(view.viewStart(), 0.0);
        QVERIFY(std::abs(view.visibleDuration() - 3.0) < 1e-9);

        const double before = view.viewStart() + 450 * view.secondsPerPixel();
        view.zoomBy(4.0, 450);
        QVERIFY(std::abs(view.visibleDuration() - 0.75) < 1e-9);
        QVERIFY(std::abs(view.viewStart() + 450 * view.secondsPerPixel() - before) < 1e-9);

        view.setViewStart(10.0); // clamped to the end
        QVERIFY(std::abs(view.viewStart() + view.visibleDuration() - 3.0) < 1e-9);

        QSignalSpy clicked(&view, &WaveformView::timeClicked);
        QTest::mouseClick(&view, Qt::LeftButton, {}, QPoint(300, 100));
        QCOMPARE(clicked.count(), 1);
        QVERIFY(std::abs(clicked.first().first().toDouble() - (view.viewStart() + 300 * view.secondsPerPixel())) < 1e-6);

        view.zoomToFit();
        const QImage image = view.grab().toImage().convertToFormat(QImage::Format_RGB32);
        int wave = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                wave += image.pixelColor(x, y) == WaveformView::waveformColor() ? 1 : 0;
        QVERIFY(wave > 1000);
        // "hello" spans [1, 2) s = pixels [200, 400): its box colour sits in the words lane.
        const int wordsY = view.laneRect(WaveformView::Lane::Words).center().y();
        QVERIFY(image.pixelColor(300, wordsY) != image.pixelColor(100, wordsY));
    }
};

QTEST_MAIN(TestWaveformView)
#include "tst_waveformview.moc"
