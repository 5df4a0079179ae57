#pragma once
// The timeline's relabel editor: over an interval of the word or phone lane, a line edit (a word)
// or an editable list of the 41 phones; Enter or a chosen phone offers the label, refused in red
// when it is not valid (tieredit::validLabel), Escape or a click elsewhere closes it. What to do
// with a valid label is the panel's (one undo step).
#include "document/TierEdits.h"

#include <QObject>
#include <QPointer>
#include <QWidget>

#include <string>

namespace lipsync::studio {

class WaveformView;

class IntervalLabelEditor : public QObject
{
    Q_OBJECT
public:
    explicit IntervalLabelEditor(WaveformView *view, QObject *parent = nullptr);

    // Opens over interval `index` of `kind` (another editor open is closed first).
    void open(TierKind kind, int index);
    void close();
    // The editor shown, or null.
    QWidget *widget() const { return m_editor; }

signals:
    // A valid label for interval `index` of `kind`; the editor has closed.
    void labelChosen(lipsync::studio::TierKind kind, int index, const std::string &label);

private:
    void commit();

    WaveformView *m_view;
    QPointer<QWidget> m_editor;
    TierKind m_kind = TierKind::Phones;
    int m_index = -1;
    bool m_closing = false;
};

} // namespace lipsync::studio
