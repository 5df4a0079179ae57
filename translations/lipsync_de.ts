<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AboutBox</name>
    <message>
        <location filename="../studio/app/AboutBox.cpp" line="9"/>
        <source>&lt;h3&gt;LipSync Studio %1&lt;/h3&gt;&lt;p&gt;Realistic lip movement from speech, after G. Englebienne, T. F. Cootes and M. Rattray, &lt;i&gt;A Probabilistic Model for Generating Realistic Lip Movements from Speech&lt;/i&gt;, Advances in Neural Information Processing Systems 20 (NIPS 2007).&lt;/p&gt;&lt;p&gt;Demo clips: GRID audio-visual corpus (Cooke, Barker, Cunningham, Shao, JASA 120(5), 2006), speaker s1, CC BY 4.0; YuNet face detector (MIT).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;LipSync Studio %1&lt;/h3&gt;&lt;p&gt;Realistische Lippenbewegungen aus Sprache, nach G. Englebienne, T. F. Cootes und M. Rattray, &lt;i&gt;A Probabilistic Model for Generating Realistic Lip Movements from Speech&lt;/i&gt;, Advances in Neural Information Processing Systems 20 (NIPS 2007).&lt;/p&gt;&lt;p&gt;Demo-Clips: GRID audio-visual corpus (Cooke, Barker, Cunningham, Shao, JASA 120(5), 2006), Sprecher s1, CC BY 4.0; YuNet-Gesichtsdetektor (MIT).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../studio/app/AboutBox.cpp" line="20"/>
        <source>About LipSync Studio</source>
        <translation>Über LipSync Studio</translation>
    </message>
</context>
<context>
    <name>AppCommands</name>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="26"/>
        <source>&amp;New Project…</source>
        <translation>&amp;Neues Projekt…</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="29"/>
        <source>&amp;Open Project…</source>
        <translation>Projekt &amp;öffnen …</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="32"/>
        <source>Open &amp;Demo Project</source>
        <translation>&amp;Demoprojekt öffnen</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="38"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="41"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="44"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="47"/>
        <source>Fit Frame to View</source>
        <translation>Bild einpassen</translation>
    </message>
    <message>
        <location filename="../studio/app/AppCommands.cpp" line="52"/>
        <source>&amp;About LipSync Studio</source>
        <translation>&amp;Über LipSync Studio</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="14"/>
        <source>LipSync Studio: realistic lip movement from speech.</source>
        <translation>LipSync Studio: realistische Lippenbewegungen aus Sprache.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="17"/>
        <source>Open the project in DIR.</source>
        <translation>Das Projekt im Ordner DIR öffnen.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="20"/>
        <source>User interface language (en, de); default: the system&apos;s.</source>
        <translation>Sprache der Benutzeroberfläche (en, de); Vorgabe: die des Systems.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="23"/>
        <source>Render the main window into FILE (PNG) once the project has loaded, then exit.</source>
        <translation>Das Hauptfenster nach dem Laden des Projekts in DATEI (PNG) speichern und beenden.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="25"/>
        <source>Window size, e.g. 1920x1080.</source>
        <translation>Fenstergröße, z. B. 1920x1080.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="28"/>
        <source>Project folder (or its project.json).</source>
        <translation>Projektordner (oder dessen project.json).</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="42"/>
        <source>--size takes WIDTHxHEIGHT, at least 320x240, e.g. 1920x1080</source>
        <translation>--size erwartet BREITExHÖHE, mindestens 320x240, z. B. 1920x1080</translation>
    </message>
</context>
<context>
    <name>ErrorReporter</name>
    <message>
        <location filename="../studio/context/ErrorReporter.cpp" line="21"/>
        <source>File: %1</source>
        <translation>Datei: %1</translation>
    </message>
    <message>
        <location filename="../studio/context/ErrorReporter.cpp" line="24"/>
        <source>Reason: %1</source>
        <translation>Grund: %1</translation>
    </message>
    <message>
        <location filename="../studio/context/ErrorReporter.cpp" line="30"/>
        <source>LipSync Studio</source>
        <translation>LipSync Studio</translation>
    </message>
</context>
<context>
    <name>ModelKinds</name>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="23"/>
        <source>DPDS</source>
        <translation>DPDS</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="25"/>
        <source>SLDS</source>
        <translation>SLDS</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="27"/>
        <source>Brand</source>
        <translation>Brand</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="29"/>
        <source>HMM-mean</source>
        <translation>HMM-Mittelwert</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="49"/>
        <source>Deterministic-process dynamical system (the paper&apos;s model)</source>
        <translation>Dynamisches System mit deterministischem Prozess (das Modell des Artikels)</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="51"/>
        <source>Switching linear dynamical system</source>
        <translation>Schaltendes lineares dynamisches System</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="53"/>
        <source>Brand&apos;s Voice Puppetry: per-phone Gaussians over position and velocity</source>
        <translation>Brands Voice Puppetry: Gauß-Verteilungen je Phon über Position und Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../studio/context/ModelKinds.cpp" line="55"/>
        <source>Phoneme-mean baseline: one Gaussian per phone, frames independent</source>
        <translation>Phonem-Mittelwert als Vergleich: eine Gauß-Verteilung je Phon, Bilder unabhängig</translation>
    </message>
</context>
<context>
    <name>MouthShapesDialog</name>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="48"/>
        <source>Opening</source>
        <translation>Öffnung</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="49"/>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="50"/>
        <source>Rounding</source>
        <translation>Rundung</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="51"/>
        <source>Teeth</source>
        <translation>Zähne</translation>
    </message>
</context>
<context>
    <name>SequenceLoader</name>
    <message>
        <location filename="../studio/context/SequenceLoader.cpp" line="48"/>
        <source>Decoding audio</source>
        <translation>Audio wird dekodiert</translation>
    </message>
    <message>
        <location filename="../studio/context/SequenceLoader.cpp" line="77"/>
        <source>Reading video frames</source>
        <translation>Videobilder werden gelesen</translation>
    </message>
    <message>
        <location filename="../studio/context/SequenceLoader.cpp" line="103"/>
        <source>Loading %1</source>
        <translation>%1 wird geladen</translation>
    </message>
</context>
<context>
    <name>SetTranscriptCommand</name>
    <message>
        <location filename="../studio/document/SetTranscriptCommand.cpp" line="15"/>
        <source>Propose transcript of %1</source>
        <translation>Transkript von %1 vorschlagen</translation>
    </message>
    <message>
        <location filename="../studio/document/SetTranscriptCommand.cpp" line="17"/>
        <source>Accept transcript of %1</source>
        <translation>Transkript von %1 übernehmen</translation>
    </message>
    <message>
        <location filename="../studio/document/SetTranscriptCommand.cpp" line="20"/>
        <source>Edit transcript of %1</source>
        <translation>Transkript von %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>StudioActions</name>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="28"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="31"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="37"/>
        <source>Previous Frame</source>
        <translation>Vorheriges Bild</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="41"/>
        <source>Next Frame</source>
        <translation>Nächstes Bild</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="45"/>
        <source>First Frame</source>
        <translation>Erstes Bild</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="48"/>
        <source>Last Frame</source>
        <translation>Letztes Bild</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="51"/>
        <source>Play/Pause</source>
        <translation>Wiedergabe/Pause</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="55"/>
        <source>Previous Sequence</source>
        <translation>Vorherige Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/context/StudioActions.cpp" line="59"/>
        <source>Next Sequence</source>
        <translation>Nächste Sequenz</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::Autosave</name>
    <message>
        <location filename="../studio/app/Autosave.cpp" line="34"/>
        <source>Recover Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <location filename="../studio/app/Autosave.cpp" line="35"/>
        <source>LipSync Studio did not close normally while %1 had unsaved changes. An autosave from %2 is newer than the saved project.</source>
        <translation>LipSync Studio wurde nicht normal beendet, während %1 ungespeicherte Änderungen hatte. Eine automatische Sicherung vom %2 ist neuer als das gespeicherte Projekt.</translation>
    </message>
    <message>
        <location filename="../studio/app/Autosave.cpp" line="40"/>
        <source>Recover opens the autosaved version as unsaved changes; Discard deletes the autosave.</source>
        <translation>„Wiederherstellen“ öffnet die automatisch gesicherte Fassung als ungespeicherte Änderungen; „Verwerfen“ löscht die automatische Sicherung.</translation>
    </message>
    <message>
        <location filename="../studio/app/Autosave.cpp" line="42"/>
        <source>Recover</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../studio/app/Autosave.cpp" line="249"/>
        <source>The autosaved changes could not be recovered; the saved project opens.</source>
        <translation>Die automatisch gesicherten Änderungen konnten nicht wiederhergestellt werden; das gespeicherte Projekt wird geöffnet.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::CameraFeed</name>
    <message>
        <location filename="../studio/live/CameraFeed.cpp" line="27"/>
        <source>No such camera.</source>
        <translation>Diese Kamera gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../studio/live/CameraFeed.cpp" line="36"/>
        <source>The camera stopped: %1</source>
        <translation>Die Kamera hat angehalten: %1</translation>
    </message>
    <message>
        <location filename="../studio/live/CameraFeed.cpp" line="41"/>
        <source>The camera %1 could not be opened: %2</source>
        <translation>Die Kamera %1 ließ sich nicht öffnen: %2</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::EvaluationChart</name>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="63"/>
        <source>L1 error</source>
        <translation>L1-Fehler</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="64"/>
        <source>RMS error</source>
        <translation>RMS-Fehler</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="65"/>
        <source>L-inf error</source>
        <translation>L-inf-Fehler</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="66"/>
        <source>log-likelihood per frame</source>
        <translation>Log-Likelihood pro Bild</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="67"/>
        <source>lip-opening correlation</source>
        <translation>Korrelation der Lippenöffnung</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="68"/>
        <source>lip-opening correlation, control</source>
        <translation>Korrelation der Lippenöffnung, Kontrolle</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="69"/>
        <source>lip-opening correlation in speech</source>
        <translation>Korrelation der Lippenöffnung beim Sprechen</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="70"/>
        <source>lip-opening correlation in speech, control</source>
        <translation>Korrelation der Lippenöffnung beim Sprechen, Kontrolle</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="72"/>
        <source>lip-opening correlation in speech, other footage</source>
        <translation>Korrelation der Lippenöffnung beim Sprechen, anderes Filmmaterial</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="76"/>
        <source>machine observer (0.5: fooled)</source>
        <translation>Maschineller Beobachter (0,5: getäuscht)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="77"/>
        <source>machine observer per video</source>
        <translation>maschineller Beobachter je Video</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="78"/>
        <source>called rendered: recorded frames</source>
        <translation>für erzeugt gehalten: aufgenommene Bilder</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="78"/>
        <source>called rendered: recording</source>
        <translation>für erzeugt gehalten: Aufnahme</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="80"/>
        <source>called rendered: face moved only</source>
        <translation>für erzeugt gehalten: nur Gesicht bewegt</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="80"/>
        <source>… face moved</source>
        <translation>… Gesicht bewegt</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="81"/>
        <source>called rendered: open mouth squeezed narrower</source>
        <translation>für erzeugt gehalten: offener Mund enger gedrückt</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="82"/>
        <source>… mouth squeezed</source>
        <translation>… Mund gedrückt</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="83"/>
        <source>called rendered: inside drawn</source>
        <translation>für erzeugt gehalten: Mundinneres gezeichnet</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="83"/>
        <source>… inside drawn</source>
        <translation>… Mundinneres gezeichnet</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="84"/>
        <source>called rendered: closed lips drawn</source>
        <translation>für erzeugt gehalten: geschlossene Lippen gezeichnet</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="84"/>
        <source>… closed lips drawn</source>
        <translation>… geschlossene Lippen gezeichnet</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="86"/>
        <source>articulation (s.d. ratio)</source>
        <translation>Artikulation (Verhältnis der Standardabweichungen)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="89"/>
        <source>/p b m/ closures (ratio)</source>
        <translation>Verschlüsse bei /p b m/ (Verhältnis)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="92"/>
        <source>/p b m/ closure recall</source>
        <translation>/p b m/-Verschlüsse getroffen</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="94"/>
        <source>false closures per s of speech</source>
        <translation>falsche Verschlüsse je s Sprache</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="95"/>
        <source>false closures per s, recording</source>
        <translation>falsche Verschlüsse je s, Aufnahme</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="97"/>
        <source>lag (frames)</source>
        <translation>Verzögerung (Bilder)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="100"/>
        <source>mouth sharpness (ratio)</source>
        <translation>Schärfe des Mundes (Verhältnis)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="103"/>
        <source>seam: colour step at the drawn edge (ΔE)</source>
        <translation>Naht: Farbsprung am gezeichneten Rand (ΔE)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="104"/>
        <source>seam: the recording&apos;s same pixels (ΔE)</source>
        <translation>Naht: dieselben Pixel der Aufnahme (ΔE)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="105"/>
        <source>seam: a real edge there (ΔE)</source>
        <translation>Naht: eine echte Kante dort (ΔE)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="106"/>
        <source>mouth drawn as generated (correlation)</source>
        <translation>Mund wie erzeugt gezeichnet (Korrelation)</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="69"/>
        <source>speech r</source>
        <translation>Sprache r</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="71"/>
        <source>speech r, control</source>
        <translation>Sprache r, Kontrolle</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="73"/>
        <source>speech r, other footage</source>
        <translation>Sprache r, anderes Material</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="67"/>
        <source>r</source>
        <translation>r</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="68"/>
        <source>r, control</source>
        <translation>r, Kontrolle</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="86"/>
        <source>articulation</source>
        <translation>Artikulation</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="89"/>
        <source>closures</source>
        <translation>Verschlüsse</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="92"/>
        <source>closure recall</source>
        <translation>Verschlüsse getroffen</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="94"/>
        <source>false closures /s</source>
        <translation>falsche Verschlüsse /s</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="95"/>
        <source>… recording</source>
        <translation>… Aufnahme</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="76"/>
        <source>observer</source>
        <translation>Beobachter</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="51"/>
        <source>The share of frames the machine observer calls rendered: among the recording&apos;s (its false alarms), and among the render&apos;s where the recording&apos;s face was only moved, where it was only moved and its open mouth squeezed narrower, where a mouth&apos;s inside was drawn, and where closed lips were drawn. Well above the recording&apos;s share: that step gives frames away.</source>
        <translation>Der Anteil der Bilder, die der maschinelle Beobachter für erzeugt hält: unter denen der Aufnahme (seine Fehlalarme) und unter denen des Renderings, in denen das Gesicht der Aufnahme nur bewegt, nur bewegt und sein offener Mund enger gedrückt, ein Mundinneres gezeichnet oder geschlossene Lippen gezeichnet wurden. Deutlich über dem Anteil der Aufnahme: dieser Schritt verrät Bilder.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="77"/>
        <source>observer, videos</source>
        <translation>Beobachter, Videos</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="100"/>
        <source>sharpness</source>
        <translation>Schärfe</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="103"/>
        <source>seam ΔE</source>
        <translation>Naht ΔE</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="104"/>
        <source>… same pixels</source>
        <translation>… dieselben Pixel</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="105"/>
        <source>… a real edge</source>
        <translation>… eine echte Kante</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="106"/>
        <source>drawn as generated r</source>
        <translation>gezeichnet wie erzeugt r</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="42"/>
        <source>Pearson correlation of the rendered lip opening, read by dlib on the rendered frames, with the recording&apos;s; in speech: from the first to the last spoken phone, leaving out the silences every clip shares.</source>
        <translation>Pearson-Korrelation der gerenderten Lippenöffnung, von dlib auf den gerenderten Bildern gelesen, mit der der Aufnahme; beim Sprechen: vom ersten bis zum letzten gesprochenen Phon, ohne die Stille, die jeder Clip hat.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="45"/>
        <source>The same correlation of each recording with another clip&apos;s render: a control that cannot be good. A method is only as good as its lead over this.</source>
        <translation>Dieselbe Korrelation jeder Aufnahme mit dem Rendering eines anderen Clips: eine Kontrolle, die nicht gut sein kann. Ein Verfahren ist nur so gut wie sein Vorsprung davor.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="74"/>
        <source>Correlation in speech with each frame drawn into the clip&apos;s footage half its length away, whose mouth does not follow the recording: new speech put into other footage.</source>
        <translation>Korrelation beim Sprechen, wenn jedes Bild in das Material des Clips eine halbe Cliplänge entfernt gezeichnet wird, dessen Mund der Aufnahme nicht folgt: neue Sprache in anderem Filmmaterial.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="48"/>
        <source>Held-out accuracy of a classifier on the mouth crop telling the render from the recording, both encoded by the same encoder. 0.5: it cannot tell them apart; the re-encoded recording shows the floor.</source>
        <translation>Genauigkeit eines Klassifikators auf zurückgehaltenen Daten, der am Mundausschnitt Rendering und Aufnahme unterscheidet, beide mit demselben Encoder kodiert. 0,5: er kann sie nicht unterscheiden; die neu kodierte Aufnahme zeigt die Untergrenze.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="87"/>
        <source>Standard deviation of the rendered lip opening over the recording&apos;s: 1 articulates as much as the speaker.</source>
        <translation>Standardabweichung der gerenderten Lippenöffnung durch die der Aufnahme: 1 artikuliert so stark wie der Sprecher.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="90"/>
        <source>/p b m/ segments the render closes over those the recording closes: 1 closes as often as the speaker does.</source>
        <translation>/p b m/-Abschnitte, die das Rendering schließt, durch die, die die Aufnahme schließt: 1 schließt so oft wie der Sprecher.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="93"/>
        <source>Of the /p b m/ segments the recording closes, the share the render closes too.</source>
        <translation>Von den /p b m/-Abschnitten, die die Aufnahme schließt, der Anteil, den auch das Rendering schließt.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="56"/>
        <source>Lip closures outside /p b m/, per second of speech (the recording&apos;s own count beside it).</source>
        <translation>Lippenverschlüsse außerhalb von /p b m/ je Sekunde Sprache (daneben die Zahl der Aufnahme selbst).</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="98"/>
        <source>Frames by which the opening lags the sound&apos;s energy, render minus recording (negative: the render leads).</source>
        <translation>Bilder, um die die Öffnung der Energie des Tons nachläuft, Rendering minus Aufnahme (negativ: das Rendering läuft vor).</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="101"/>
        <source>Mean squared Laplacian of the mouth box over the recording&apos;s: above 1 is crisper than the video.</source>
        <translation>Mittleres Quadrat des Laplace-Filters im Mundbereich durch das der Aufnahme: über 1 ist schärfer als das Video.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="58"/>
        <source>CIE Lab ΔE across the edge of what the renderer drew: on the render, on the recording at the same pixels, and across a real edge there (for a drawn mouth inside: the recording&apos;s own inner-lip edge at that opening). A seam shows where the render&apos;s step exceeds a real one.</source>
        <translation>CIE-Lab-ΔE über den Rand dessen, was der Renderer zeichnete: im Rendering, in der Aufnahme an denselben Pixeln und über eine echte Kante dort (für ein gezeichnetes Mundinneres: die eigene Innenlippenkante der Aufnahme bei dieser Öffnung). Eine Naht ist sichtbar, wo der Sprung des Renderings den einer echten Kante übersteigt.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="107"/>
        <source>The method&apos;s own inner-lip gap, as the animation exports carry it, against the opening read on its render.</source>
        <translation>Der eigene Innenlippenabstand des Verfahrens, wie ihn die Animationsexporte tragen, gegen die auf seinem Rendering gelesene Öffnung.</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="222"/>
        <source>tracked</source>
        <translation>verfolgt</translation>
    </message>
    <message>
        <location filename="../studio/plots/EvaluationChart.cpp" line="220"/>
        <source>recording, re-encoded</source>
        <translation>Aufnahme, neu kodiert</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ExportMenu</name>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="110"/>
        <source>E&amp;xport</source>
        <translation>E&amp;xportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="114"/>
        <source>F&amp;eatures (CSV)…</source>
        <translation>M&amp;erkmale (CSV)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="114"/>
        <location filename="../studio/export/ExportMenu.cpp" line="180"/>
        <source>Generated &amp;Frames%1 (PNG)…</source>
        <translation>Erzeugte &amp;Einzelbilder%1 (PNG)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="115"/>
        <source>&amp;Alignment (TextGrid)…</source>
        <translation>&amp;Alignierung (TextGrid)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="115"/>
        <source>&amp;Landmarks (.pts)…</source>
        <translation>&amp;Landmarken (.pts)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="116"/>
        <source>Active Appearance &amp;Model…</source>
        <translation>Active Appearance &amp;Model…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="116"/>
        <source>&amp;Trained Dynamic Model…</source>
        <translation>&amp;Trainiertes dynamisches Modell…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="117"/>
        <location filename="../studio/export/ExportMenu.cpp" line="181"/>
        <source>Mouth &amp;Cues%1 (Rhubarb, Moho)…</source>
        <translation>Mund&amp;formen%1 (Rhubarb, Moho)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="117"/>
        <location filename="../studio/export/ExportMenu.cpp" line="182"/>
        <source>Animation C&amp;ontrols%1 (JSON, CSV)…</source>
        <translation>Animations&amp;regler%1 (JSON, CSV)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="134"/>
        <source>Mouth S&amp;hapes…</source>
        <translation>&amp;Mundbilder…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="139"/>
        <source>The nine mouth shapes of the cues, learned from this person&apos;s frames: see them and set your own</source>
        <translation>Die neun Mundbilder der Mundformen, gelernt aus den Bildern dieser Person: ansehen und eigene festlegen</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="146"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="146"/>
        <source>Which trained model?</source>
        <translation>Welches trainierte Modell?</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="177"/>
        <source> of %1</source>
        <translation> von %1</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="251"/>
        <location filename="../studio/export/ExportMenu.cpp" line="252"/>
        <source>MP4 video (*.mp4)</source>
        <translation>MP4-Video (*.mp4)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="254"/>
        <source>Feature tables (*.csv)</source>
        <translation>Merkmalstabellen (*.csv)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="255"/>
        <source>Praat TextGrid (*.TextGrid)</source>
        <translation>Praat-TextGrid (*.TextGrid)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="257"/>
        <source>Active appearance models (*.aam)</source>
        <translation>Active Appearance Models (*.aam)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="259"/>
        <source>Dynamic models (*.model)</source>
        <translation>Dynamische Modelle (*.model)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="260"/>
        <source>Rhubarb TSV (*.tsv);;Rhubarb JSON (*.json);;Rhubarb XML (*.xml);;Moho switch data (*.dat)</source>
        <translation>Rhubarb TSV (*.tsv);;Rhubarb JSON (*.json);;Rhubarb XML (*.xml);;Moho-Schaltdaten (*.dat)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="261"/>
        <source>Controls JSON (*.json);;Controls CSV (*.csv)</source>
        <translation>Regler JSON (*.json);;Regler CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="276"/>
        <location filename="../studio/export/ExportMenu.cpp" line="320"/>
        <location filename="../studio/export/ExportMenu.cpp" line="378"/>
        <location filename="../studio/export/ExportMenu.cpp" line="445"/>
        <location filename="../studio/export/ExportMenu.cpp" line="485"/>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="278"/>
        <source>no sequence is selected</source>
        <translation>keine Sequenz ausgewählt</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="329"/>
        <source>%1 has no video to put beside the generated face</source>
        <translation>%1 hat kein Video, neben das das erzeugte Gesicht gestellt werden könnte</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="343"/>
        <source>the project has no trained dynamic model and AAM (train one in the Models panel)</source>
        <translation>das Projekt hat kein trainiertes dynamisches Modell und kein AAM (im Bereich Modelle trainieren)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="490"/>
        <source>the project has no AAM (build one in the Models panel)</source>
        <translation>das Projekt hat kein AAM (im Modelle-Bereich erstellen)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="497"/>
        <source>%1 needs face features and a phone alignment (track and align it first)</source>
        <translation>%1 braucht Gesichtsmerkmale und eine Lautausrichtung (zuerst verfolgen und ausrichten)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="506"/>
        <source>Export the mouth cues of %1</source>
        <translation>Mundformen von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="506"/>
        <source>Export the animation controls of %1</source>
        <translation>Animationsregler von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="334"/>
        <location filename="../studio/export/ExportMenu.cpp" line="358"/>
        <source>Export the generated frames of %1</source>
        <translation>Erzeugte Einzelbilder von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="113"/>
        <location filename="../studio/export/ExportMenu.cpp" line="178"/>
        <source>Generated &amp;Video%1 (MP4)…</source>
        <translation>Erzeugtes &amp;Video%1 (MP4)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="113"/>
        <location filename="../studio/export/ExportMenu.cpp" line="179"/>
        <source>Real and Generated &amp;Side by Side%1 (MP4)…</source>
        <translation>Echt und erzeugt &amp;nebeneinander%1 (MP4)…</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="335"/>
        <location filename="../studio/export/ExportMenu.cpp" line="359"/>
        <source>Export the generated video of %1</source>
        <translation>Erzeugtes Video von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="384"/>
        <source>%1 has no face features (track it first)</source>
        <translation>%1 hat keine Gesichtsmerkmale (zuerst tracken)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="387"/>
        <source>Export the features of %1</source>
        <translation>Merkmale von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="395"/>
        <source>%1 has no phone alignment (align it first)</source>
        <translation>%1 hat keine Phonem-Alignierung (zuerst alignieren)</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="398"/>
        <source>Export the alignment of %1</source>
        <translation>Alignierung von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="411"/>
        <source>%1 has no landmarks</source>
        <translation>%1 hat keine Landmarken</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="414"/>
        <source>Export the landmarks of %1</source>
        <translation>Landmarken von %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="450"/>
        <source>the project has no AAM</source>
        <translation>das Projekt hat kein AAM</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="451"/>
        <source>the project has no trained dynamic model</source>
        <translation>das Projekt hat kein trainiertes dynamisches Modell</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="455"/>
        <source>Export %1</source>
        <translation>%1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/export/ExportMenu.cpp" line="301"/>
        <source>Exported to %1</source>
        <translation>Exportiert nach %1</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::FacesController</name>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="84"/>
        <source>&amp;Detect Landmarks</source>
        <translation>Landmarken &amp;erkennen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="85"/>
        <source>&amp;Copy Previous Frame&apos;s Points</source>
        <translation>Punkte des vorigen Bildes &amp;kopieren</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="86"/>
        <source>&amp;Onion Skin of Previous Frame</source>
        <translation>&amp;Onion-Skin (vorheriges Bild)</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="88"/>
        <source>Next &amp;Unlabelled Frame</source>
        <translation>Nächstes &amp;unbeschriftetes Bild</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="89"/>
        <source>Next &amp;Worst-Fitted Frame</source>
        <translation>Nächstes &amp;schlecht angepasstes Bild</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="90"/>
        <source>&amp;Pick Frames to Label…</source>
        <translation>Bilder zum &amp;Beschriften auswählen…</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="91"/>
        <source>Next &amp;Picked Frame to Review</source>
        <translation>Nächstes ausgewähltes Bild &amp;prüfen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="92"/>
        <source>&amp;Build AAM</source>
        <translation>AAM e&amp;rstellen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="93"/>
        <source>&amp;Track Sequence</source>
        <translation>Sequenz &amp;tracken</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="94"/>
        <source>Track &amp;All Sequences</source>
        <translation>&amp;Alle Sequenzen tracken</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="95"/>
        <source>&amp;Modes of Variation…</source>
        <translation>&amp;Variationsmoden…</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="97"/>
        <source>Fa&amp;ces</source>
        <translation>&amp;Gesichter</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="126"/>
        <source>Pick Frames to Label</source>
        <translation>Bilder zum Beschriften auswählen</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/annotate/FacesController.cpp" line="127"/>
        <source>Frames to pick from the %n clip(s) (an AAM with the paper&apos;s 32 parameters wants 100-200):</source>
        <translation>
            <numerusform>Anzahl der Bilder aus dem Clip (ein AAM mit den 32 Parametern des Artikels braucht 100–200):</numerusform>
            <numerusform>Anzahl der Bilder aus den %n Clips (ein AAM mit den 32 Parametern des Artikels braucht 100–200):</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="255"/>
        <source>Fit error %1</source>
        <translation>Anpassungsfehler %1</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="256"/>
        <source>No face found by the tracker</source>
        <translation>Der Tracker hat kein Gesicht gefunden</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="280"/>
        <source>Detect landmarks in %1, frame %2</source>
        <translation>Landmarken in %1, Bild %2 erkennen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="282"/>
        <source>Finding the face…</source>
        <translation>Gesicht wird gesucht…</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="309"/>
        <source>Detect landmarks in frame %1</source>
        <translation>Landmarken in Bild %1 erkennen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="312"/>
        <source>No landmarks were detected.</source>
        <translation>Es wurden keine Landmarken erkannt.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/annotate/FacesController.cpp" line="330"/>
        <location filename="../studio/annotate/FacesController.cpp" line="368"/>
        <source>Pick %n frame(s) to label</source>
        <translation>
            <numerusform>%n Bild zum Beschriften auswählen</numerusform>
            <numerusform>%n Bilder zum Beschriften auswählen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/annotate/FacesController.cpp" line="376"/>
        <source>Picked %1 of %2 frames with a face from %n clip(s); Shift+W shows them, the most doubtful first, then Build AAM.</source>
        <translation>
            <numerusform>%1 von %2 Bildern mit Gesicht aus einem Clip ausgewählt; Umschalt+W zeigt sie, die zweifelhaftesten zuerst, danach AAM erstellen.</numerusform>
            <numerusform>%1 von %2 Bildern mit Gesicht aus %n Clips ausgewählt; Umschalt+W zeigt sie, die zweifelhaftesten zuerst, danach AAM erstellen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="384"/>
        <source>No frames could be picked.</source>
        <translation>Es konnten keine Bilder ausgewählt werden.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="393"/>
        <source>Picked frame %1 of %2: %3, frame %4</source>
        <translation>Ausgewähltes Bild %1 von %2: %3, Bild %4</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="399"/>
        <source> (fit not measured)</source>
        <translation> (Anpassung nicht gemessen)</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="402"/>
        <source>; an AAM built without it moves its points by %1 % of the eye distance (most doubtful first)</source>
        <translation>; ein AAM ohne dieses Bild verschiebt seine Punkte um %1 % des Augenabstands (das zweifelhafteste zuerst)</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="446"/>
        <source>Copy points of frame %1 to frame %2</source>
        <translation>Punkte von Bild %1 nach Bild %2 kopieren</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="465"/>
        <source>Every frame of this sequence is labelled.</source>
        <translation>Alle Bilder dieser Sequenz sind beschriftet.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="475"/>
        <source>Track this sequence first to rank its frames by fit error.</source>
        <translation>Tracken Sie diese Sequenz zuerst, um ihre Bilder nach Anpassungsfehler zu ordnen.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="504"/>
        <source>The project&apos;s AAM could not be loaded.</source>
        <translation>Das AAM des Projekts konnte nicht geladen werden.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="528"/>
        <source>An AAM needs at least 3 frames with all 23 points; this project has %1.</source>
        <translation>Ein AAM braucht mindestens 3 Bilder mit allen 23 Punkten; dieses Projekt hat %1.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="530"/>
        <source>Label more frames (Detect Landmarks, then correct the points).</source>
        <translation>Beschriften Sie weitere Bilder (Landmarken erkennen, dann die Punkte korrigieren).</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/annotate/FacesController.cpp" line="539"/>
        <source>Build AAM from %n frame(s)</source>
        <translation>
            <numerusform>AAM aus %n Bild erstellen</numerusform>
            <numerusform>AAM aus %n Bildern erstellen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="541"/>
        <source>Reading the labelled frames…</source>
        <translation>Beschriftete Bilder werden gelesen…</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="569"/>
        <source>Build AAM %1</source>
        <translation>AAM %1 erstellen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="571"/>
        <source>AAM %1 built from %2 frames: %3 combined modes%4</source>
        <translation>AAM %1 aus %2 Bildern erstellt: %3 kombinierte Moden%4</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/annotate/FacesController.cpp" line="575"/>
        <source> (%n frame(s) skipped)</source>
        <translation>
            <numerusform> (%n Bild übersprungen)</numerusform>
            <numerusform> (%n Bilder übersprungen)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="580"/>
        <source>The AAM could not be built.</source>
        <translation>Das AAM konnte nicht erstellt werden.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="595"/>
        <source>Tracking needs an AAM.</source>
        <translation>Zum Tracken wird ein AAM benötigt.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="596"/>
        <source>Label a few frames and choose Faces ▸ Build AAM first.</source>
        <translation>Beschriften Sie einige Bilder und wählen Sie zuerst Gesichter ▸ AAM erstellen.</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="614"/>
        <source>Track %1</source>
        <translation>%1 tracken</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/annotate/FacesController.cpp" line="614"/>
        <source>Track %n sequence(s)</source>
        <translation>
            <numerusform>%n Sequenz tracken</numerusform>
            <numerusform>%n Sequenzen tracken</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/annotate/FacesController.cpp" line="682"/>
        <source>Tracking failed.</source>
        <translation>Das Tracking ist fehlgeschlagen.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::FrameView</name>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="307"/>
        <source>Click to place %1 (%2 of %3), or press %4 to detect all points</source>
        <translation>Klicken, um %1 zu setzen (%2 von %3), oder %4 drücken, um alle Punkte zu erkennen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="280"/>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="281"/>
        <source>placed</source>
        <translation>gesetzt</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="282"/>
        <source>fixed</source>
        <translation>fixiert</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="313"/>
        <source>Click to place %1 (%2 of %3)</source>
        <translation>Klicken, um %1 zu setzen (%2 von %3)</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="315"/>
        <source>Selected: %1</source>
        <translation>Ausgewählt: %1</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="357"/>
        <source>Place %1</source>
        <translation>%1 setzen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="399"/>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="431"/>
        <source>Remove %1</source>
        <translation>%1 entfernen</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="117"/>
        <source>left eye, outer corner</source>
        <translation>linkes Auge, äußerer Winkel</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="118"/>
        <source>left eye, upper lid</source>
        <translation>linkes Auge, Oberlid</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="119"/>
        <source>left eye, inner corner</source>
        <translation>linkes Auge, innerer Winkel</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="120"/>
        <source>left eye, lower lid</source>
        <translation>linkes Auge, Unterlid</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="121"/>
        <source>right eye, inner corner</source>
        <translation>rechtes Auge, innerer Winkel</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="122"/>
        <source>right eye, upper lid</source>
        <translation>rechtes Auge, Oberlid</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="123"/>
        <source>right eye, outer corner</source>
        <translation>rechtes Auge, äußerer Winkel</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="124"/>
        <source>right eye, lower lid</source>
        <translation>rechtes Auge, Unterlid</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="125"/>
        <source>mouth, left corner</source>
        <translation>Mund, linker Winkel</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="126"/>
        <source>upper lip, left</source>
        <translation>Oberlippe, links</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="127"/>
        <source>upper lip, centre</source>
        <translation>Oberlippe, Mitte</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="128"/>
        <source>upper lip, right</source>
        <translation>Oberlippe, rechts</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="129"/>
        <source>mouth, right corner</source>
        <translation>Mund, rechter Winkel</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="130"/>
        <source>lower lip, right</source>
        <translation>Unterlippe, rechts</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="131"/>
        <source>lower lip, centre</source>
        <translation>Unterlippe, Mitte</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="132"/>
        <source>lower lip, left</source>
        <translation>Unterlippe, links</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="133"/>
        <source>inner lip, top</source>
        <translation>Innenlippe, oben</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="134"/>
        <source>inner lip, bottom</source>
        <translation>Innenlippe, unten</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="135"/>
        <source>jaw, left</source>
        <translation>Kiefer, links</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="136"/>
        <source>jaw, lower left</source>
        <translation>Kiefer, unten links</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="137"/>
        <source>chin</source>
        <translation>Kinn</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="138"/>
        <source>jaw, lower right</source>
        <translation>Kiefer, unten rechts</translation>
    </message>
    <message>
        <location filename="../studio/annotate/FrameView.cpp" line="139"/>
        <source>jaw, right</source>
        <translation>Kiefer, rechts</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ImportLongRecordingDialog</name>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="25"/>
        <source>Import Long Recording</source>
        <translation>Lange Aufnahme importieren</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="28"/>
        <source>A long recording of one speaker is aligned to its transcript and cut at its pauses into utterances. Each becomes a sequence of the project with its words and alignment; its clip is written into the project&apos;s clips folder.</source>
        <translation>Eine lange Aufnahme eines Sprechers wird an ihrem Transkript aligniert und an ihren Pausen in Äußerungen geschnitten. Jede wird eine Sequenz des Projekts mit ihren Wörtern und ihrem Alignment; ihr Clip wird in den Clip-Ordner des Projekts geschrieben.</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="41"/>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="49"/>
        <source>&amp;Recording:</source>
        <translation>&amp;Aufnahme:</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="49"/>
        <source>A video or sound file</source>
        <translation>Eine Video- oder Tondatei</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="50"/>
        <source>&amp;Transcript:</source>
        <translation>&amp;Transkript:</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="51"/>
        <source>The words spoken: .txt, .srt, .vtt, .lab, .align or .TextGrid</source>
        <translation>Die gesprochenen Wörter: .txt, .srt, .vtt, .lab, .align oder .TextGrid</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="57"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="62"/>
        <source>A silence this long ends an utterance once it is long enough</source>
        <translation>Eine so lange Stille beendet eine Äußerung, sobald diese lang genug ist</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="63"/>
        <source>How long an utterance lasts before a pause ends it</source>
        <translation>Wie lange eine Äußerung dauert, bevor eine Pause sie beendet</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="65"/>
        <source>Beyond this, the longest silence so far (or else a word boundary) ends an utterance</source>
        <translation>Darüber hinaus beendet die bisher längste Stille (sonst eine Wortgrenze) eine Äußerung</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="66"/>
        <source>&amp;Pause that ends an utterance:</source>
        <translation>&amp;Pause, die eine Äußerung beendet:</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="67"/>
        <source>&amp;Shortest utterance:</source>
        <translation>&amp;Kürzeste Äußerung:</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="68"/>
        <source>L&amp;ongest utterance:</source>
        <translation>&amp;Längste Äußerung:</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="73"/>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="131"/>
        <source>Choose the Recording</source>
        <translation>Aufnahme wählen</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="132"/>
        <source>Video and sound (*.mp4 *.mov *.mkv *.avi *.webm *.mpg *.wav *.flac *.mp3 *.ogg *.m4a);;All files (*)</source>
        <translation>Video und Ton (*.mp4 *.mov *.mkv *.avi *.webm *.mpg *.wav *.flac *.mp3 *.ogg *.m4a);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="141"/>
        <source>Choose the Transcript</source>
        <translation>Transkript wählen</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="142"/>
        <source>Transcripts (*.txt *.srt *.vtt *.lab *.align *.TextGrid);;All files (*)</source>
        <translation>Transkripte (*.txt *.srt *.vtt *.lab *.align *.TextGrid);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="151"/>
        <source>Choose the recording: a video or sound file.</source>
        <translation>Wählen Sie die Aufnahme: eine Video- oder Tondatei.</translation>
    </message>
    <message>
        <location filename="../studio/app/ImportLongRecordingDialog.cpp" line="153"/>
        <source>Choose the transcript of the recording.</source>
        <translation>Wählen Sie das Transkript der Aufnahme.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::IntervalLabelEditor</name>
    <message>
        <location filename="../studio/timeline/IntervalLabelEditor.cpp" line="98"/>
        <source>Not one of the 41 phones (ARPAbet, sil, br)</source>
        <translation>Keines der 41 Phone (ARPAbet, sil, br)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/IntervalLabelEditor.cpp" line="99"/>
        <source>Enter one word</source>
        <translation>Ein einzelnes Wort eingeben</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::LiveController</name>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="105"/>
        <source>Open a project to go live: the face is drawn with its appearance model and animated by its trained dynamic model.</source>
        <translation>Öffnen Sie ein Projekt, um live zu gehen: Das Gesicht wird mit seinem Erscheinungsmodell gezeichnet und von seinem trainierten dynamischen Modell bewegt.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="109"/>
        <source>The project has no appearance model. Build one (Faces ▸ Build AAM), then train a dynamic model in the Models panel.</source>
        <translation>Das Projekt hat kein Erscheinungsmodell. Erstellen Sie eines (Gesichter ▸ AAM erstellen) und trainieren Sie dann ein dynamisches Modell im Bereich „Modelle“.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="114"/>
        <source>The project&apos;s appearance model could not be loaded: %1</source>
        <translation>Das Erscheinungsmodell des Projekts konnte nicht geladen werden: %1</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="116"/>
        <source>No dynamic model is trained yet. Train one in the Models panel (DPDS follows live speech best), then start again.</source>
        <translation>Es ist noch kein dynamisches Modell trainiert. Trainieren Sie eines im Bereich „Modelle“ (DPDS folgt Live-Sprache am besten) und starten Sie dann erneut.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="120"/>
        <source>Choose a trained model.</source>
        <translation>Wählen Sie ein trainiertes Modell.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="122"/>
        <source>The %1 model was trained with another appearance model: train it again in the Models panel.</source>
        <translation>Das Modell %1 wurde mit einem anderen Erscheinungsmodell trainiert: Trainieren Sie es im Bereich „Modelle“ erneut.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="127"/>
        <source>CMU Sphinx&apos;s US-English models, which recognise the phones when the timeline aligns with CMU Sphinx, were not found. Install the Debian package pocketsphinx-en-us, or choose the built-in model in the timeline&apos;s Model menu.</source>
        <translation>Die US-englischen Modelle von CMU Sphinx, die die Phone erkennen, wenn die Zeitleiste mit CMU Sphinx ausrichtet, wurden nicht gefunden. Installieren Sie das Debian-Paket pocketsphinx-en-us oder wählen Sie im Modell-Menü der Zeitleiste das eingebaute Modell.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="131"/>
        <source>The studio&apos;s aligner model, which recognises the phones, was not found. Reinstall the studio or point LIPSYNC_ALIGNER_MODEL at an aligner model.</source>
        <translation>Das Aligner-Modell des Studios, das die Phone erkennt, wurde nicht gefunden. Installieren Sie das Studio neu oder lassen Sie LIPSYNC_ALIGNER_MODEL auf ein Aligner-Modell zeigen.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="134"/>
        <source>The phone bigram for live recognition (aligner/grid-s1.bigram) was not found. Reinstall the studio.</source>
        <translation>Das Phon-Bigramm für die Live-Erkennung (aligner/grid-s1.bigram) wurde nicht gefunden. Installieren Sie das Studio neu.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="173"/>
        <source>A live session is running already.</source>
        <translation>Es läuft bereits eine Live-Sitzung.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="175"/>
        <source>Wait until the video export has ended.</source>
        <translation>Warten Sie, bis der Videoexport beendet ist.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="179"/>
        <source>Choose a microphone.</source>
        <translation>Wählen Sie ein Mikrofon.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="208"/>
        <source>Prepare the live view</source>
        <translation>Live-Ansicht vorbereiten</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="265"/>
        <source>No face was found in %1: the live face is drawn on grey.</source>
        <translation>In %1 wurde kein Gesicht gefunden: Das Live-Gesicht wird auf Grau gezeichnet.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="275"/>
        <source>The live view could not be prepared: %1</source>
        <translation>Die Live-Ansicht konnte nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="325"/>
        <source>The microphone could not be opened: %1.</source>
        <translation>Das Mikrofon konnte nicht geöffnet werden: %1.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="421"/>
        <source>The live session stopped: %1</source>
        <translation>Die Live-Sitzung wurde abgebrochen: %1</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="521"/>
        <location filename="../studio/live/LiveController.cpp" line="582"/>
        <source>Nothing is recorded yet: start a session and stop it first.</source>
        <translation>Es ist noch nichts aufgenommen: Starten und beenden Sie zuerst eine Sitzung.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="523"/>
        <source>No project is open.</source>
        <translation>Es ist kein Projekt geöffnet.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="525"/>
        <source>The bundled demo is read-only: save the project in a folder of your own first.</source>
        <translation>Das mitgelieferte Demo ist schreibgeschützt: Speichern Sie das Projekt zuerst in einem eigenen Ordner.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="527"/>
        <source>The project&apos;s appearance model changed since the recording: its features no longer fit.</source>
        <translation>Das Erscheinungsmodell des Projekts hat sich seit der Aufnahme geändert: Ihre Merkmale passen nicht mehr dazu.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="546"/>
        <source>The sound could not be written: %1</source>
        <translation>Der Ton konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="567"/>
        <source>Save Live Session as %1</source>
        <translation>Live-Sitzung als %1 speichern</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="569"/>
        <source>The project refused the new sequence (the status bar says why).</source>
        <translation>Das Projekt hat die neue Sequenz abgelehnt (die Statusleiste nennt den Grund).</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="584"/>
        <source>Stop the session first.</source>
        <translation>Beenden Sie zuerst die Sitzung.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="586"/>
        <source>A video export is running already.</source>
        <translation>Es läuft bereits ein Videoexport.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="598"/>
        <source>Export the live session to %1</source>
        <translation>Live-Sitzung nach %1 exportieren</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="609"/>
        <source>The live session was written to %1.</source>
        <translation>Die Live-Sitzung wurde nach %1 geschrieben.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveController.cpp" line="617"/>
        <source>The video could not be written: %1</source>
        <translation>Das Video konnte nicht geschrieben werden: %1</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::LiveView</name>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="40"/>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="41"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="41"/>
        <location filename="../studio/live/LiveView.cpp" line="461"/>
        <source>Save as Sequence</source>
        <translation>Als Sequenz speichern</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="42"/>
        <source>Export Video…</source>
        <translation>Video exportieren…</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="52"/>
        <source>Microphone:</source>
        <translation>Mikrofon:</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="54"/>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="59"/>
        <source>The microphone the face listens to</source>
        <translation>Das Mikrofon, dem das Gesicht zuhört</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="63"/>
        <source>Draw the face over a camera&apos;s picture of you, wherever your face is in it, or into the still of the person (No camera)</source>
        <translation>Das Gesicht über das Kamerabild von Ihnen zeichnen, wo immer Ihr Gesicht darin ist, oder in das Standbild der Person (Keine Kamera)</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="66"/>
        <source>The trained dynamic model that moves the face</source>
        <translation>Das trainierte dynamische Modell, das das Gesicht bewegt</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="69"/>
        <source>Listen to the microphone and move the face as you speak</source>
        <translation>Dem Mikrofon zuhören und das Gesicht bewegen, während Sie sprechen</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="72"/>
        <source>Stop listening; the session is kept for Save and Export</source>
        <translation>Nicht mehr zuhören; die Sitzung bleibt zum Speichern und Exportieren erhalten</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="74"/>
        <source>Add the last session to the project as a sequence: its sound, generated faces and recognised phones</source>
        <translation>Die letzte Sitzung als Sequenz zum Projekt hinzufügen: ihren Ton, die erzeugten Gesichter und die erkannten Phone</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="77"/>
        <source>Write the last session&apos;s faces with its sound as an MP4 video</source>
        <translation>Die Gesichter der letzten Sitzung mit ihrem Ton als MP4-Video schreiben</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="103"/>
        <source>What recognises the phones: CMU Sphinx&apos;s US-English model when the timeline aligns with CMU Sphinx (its Model menu), else the HMMs of the studio&apos;s aligner model, trained on one speaker</source>
        <translation>Was die Phone erkennt: das US-englische Modell von CMU Sphinx, wenn die Zeitleiste mit CMU Sphinx ausrichtet (ihr Modell-Menü), sonst die HMMs des Ausrichtungsmodells des Studios, auf einen Sprecher trainiert</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="107"/>
        <source>The phones recognised in the last seconds, the newest on the right</source>
        <translation>Die in den letzten Sekunden erkannten Phone, die neuesten rechts</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="113"/>
        <source>Time from the sound to the frame that shows it, over the last %1 seconds</source>
        <translation>Zeit vom Ton bis zum Bild, das ihn zeigt, über die letzten %1 Sekunden</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="211"/>
        <source>No microphone found</source>
        <translation>Kein Mikrofon gefunden</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="214"/>
        <source>A recording…</source>
        <translation>Eine Aufnahme…</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="216"/>
        <source>An audio or video file, played aloud, drives the face as if spoken now</source>
        <translation>Eine Audio- oder Videodatei, hörbar abgespielt, bewegt das Gesicht, als würde sie jetzt gesprochen</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="227"/>
        <source>No camera</source>
        <translation>Keine Kamera</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="228"/>
        <source>The face is drawn into a still of the person</source>
        <translation>Das Gesicht wird in ein Standbild der Person gezeichnet</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="277"/>
        <source>No trained model</source>
        <translation>Kein trainiertes Modell</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="310"/>
        <source>No microphone was found. Connect one (the list above follows the devices as they come and go), or choose A recording… there.</source>
        <translation>Es wurde kein Mikrofon gefunden. Schließen Sie eines an (die Liste oben folgt den Geräten, wie sie kommen und gehen), oder wählen Sie dort Eine Aufnahme….</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="320"/>
        <source>Phones: CMU Sphinx US English (any speaker)</source>
        <translation>Phone: CMU Sphinx US-Englisch (jeder Sprecher)</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="321"/>
        <source>Phones: the aligner model&apos;s HMMs</source>
        <translation>Phone: die HMMs des Ausrichtungsmodells</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="327"/>
        <source>Preparing: loading the phone recogniser and finding the face in the current sequence…</source>
        <translation>Vorbereitung: Die Phon-Erkennung wird geladen und das Gesicht in der aktuellen Sequenz gesucht…</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="331"/>
        <source>Playing %1: the face follows its sound.</source>
        <translation>%1 wird abgespielt: Das Gesicht folgt ihrem Ton.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="332"/>
        <source>Listening. Speak, and the face follows.</source>
        <translation>Hört zu. Sprechen Sie, und das Gesicht folgt.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="335"/>
        <source>Finishing the last frames…</source>
        <translation>Die letzten Bilder werden fertiggestellt…</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="341"/>
        <source>Writing the video…</source>
        <translation>Das Video wird geschrieben…</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="343"/>
        <source>The last session (%1 s) is kept: save it as a sequence, export it as a video, or start again.</source>
        <translation>Die letzte Sitzung (%1 s) ist erhalten: Speichern Sie sie als Sequenz, exportieren Sie sie als Video oder starten Sie erneut.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="350"/>
        <source>Press Start and speak: the face moves with your voice.</source>
        <translation>Drücken Sie „Start“ und sprechen Sie: Das Gesicht bewegt sich mit Ihrer Stimme.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="355"/>
        <source>This model&apos;s file predates Live&apos;s guess of phones in context, so its face waits for each phone to end, in pauses for seconds. Train it again for a face that follows at once.</source>
        <translation>Die Datei dieses Modells ist älter als Lives Schätzung der Phone im Kontext, daher wartet sein Gesicht auf das Ende jedes Phons, in Pausen sekundenlang. Trainieren Sie es neu, damit das Gesicht sofort folgt.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="359"/>
        <source>Only the first %1 minutes are kept for saving; the face went on moving after that.</source>
        <translation>Nur die ersten %1 Minuten bleiben zum Speichern erhalten; das Gesicht hat sich danach weiterbewegt.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="379"/>
        <source>Latency: %1 ms mean, %2 ms max</source>
        <translation>Latenz: %1 ms im Mittel, %2 ms maximal</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="382"/>
        <source>Time from the sound to the frame that shows it, over the last %1 seconds; %2 ms of it the phone recogniser and the model wait for the sound that follows</source>
        <translation>Zeit vom Ton bis zum Bild, das ihn zeigt, über die letzten %1 Sekunden; %2 ms davon warten die Phon-Erkennung und das Modell auf den folgenden Ton</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="387"/>
        <source>Latency: –</source>
        <translation>Latenz: –</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="389"/>
        <source>%1 s, frame %2 at %3 fps</source>
        <translation>%1 s, Bild %2 bei %3 fps</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="401"/>
        <source>Live from a Recording</source>
        <translation>Live aus einer Aufnahme</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="402"/>
        <source>Audio and video (*.wav *.flac *.mp3 *.ogg *.m4a *.mpg *.mp4 *.mov *.avi *.mkv *.webm);;All files (*)</source>
        <translation>Audio und Video (*.wav *.flac *.mp3 *.ogg *.m4a *.mpg *.mp4 *.mov *.avi *.mkv *.webm);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="462"/>
        <source>The session&apos;s sound is written into the project&apos;s folder, and the bundled demo is read-only. Save the project in a folder of your own first?</source>
        <translation>Der Ton der Sitzung wird in den Ordner des Projekts geschrieben, und das mitgelieferte Demo ist schreibgeschützt. Das Projekt zuerst in einem eigenen Ordner speichern?</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="471"/>
        <source>The live session is sequence %1, at the end of the list.</source>
        <translation>Die Live-Sitzung ist jetzt die Sequenz %1 am Ende der Liste.</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="478"/>
        <source>Export Live Session</source>
        <translation>Live-Sitzung exportieren</translation>
    </message>
    <message>
        <location filename="../studio/live/LiveView.cpp" line="480"/>
        <source>MP4 video (*.mp4)</source>
        <translation>MP4-Video (*.mp4)</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::LongRecordingImporter</name>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="46"/>
        <source>Import &amp;Long Recording…</source>
        <translation>&amp;Lange Aufnahme importieren…</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="50"/>
        <source>Align a long recording of one speaker to its transcript and add its utterances to the project as sequences</source>
        <translation>Eine lange Aufnahme eines Sprechers an ihrem Transkript alignieren und ihre Äußerungen dem Projekt als Sequenzen hinzufügen</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="78"/>
        <source>Import Long Recording</source>
        <translation>Lange Aufnahme importieren</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="79"/>
        <source>The recording&apos;s clips are written into the project&apos;s folder, and the bundled demo is read-only. Save the project in a folder of your own first?</source>
        <translation>Die Clips der Aufnahme werden in den Ordner des Projekts geschrieben, und das mitgelieferte Demo ist schreibgeschützt. Das Projekt zuerst in einem eigenen Ordner speichern?</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="97"/>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="174"/>
        <source>The long recording could not be imported.</source>
        <translation>Die lange Aufnahme konnte nicht importiert werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="98"/>
        <source>The bundled demo is read-only: save the project in a folder of your own first.</source>
        <translation>Das mitgelieferte Demo ist schreibgeschützt: Speichern Sie das Projekt zuerst in einem eigenen Ordner.</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="122"/>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="155"/>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="159"/>
        <source>Imported from %1: %2 sequences, %3 words, cut with the built-in model (the recording is longer than Generic US English aligns): Align All aligns them again with it.</source>
        <translation>Aus %1 importiert: %2 Sequenzen, %3 Wörter, geschnitten mit dem eingebauten Modell (die Aufnahme ist länger, als Allgemeines US-Englisch aligniert): „Alle ausrichten“ richtet sie damit neu aus.</translation>
    </message>
    <message>
        <location filename="../studio/app/LongRecordingImporter.cpp" line="167"/>
        <source>Imported from %1: %2 sequences, %3 words.</source>
        <translation>Aus %1 importiert: %2 Sequenzen, %3 Wörter.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::MainWindow</name>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="82"/>
        <source>Annotate</source>
        <translation>Annotieren</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="83"/>
        <source>Preview &amp;&amp; Compare</source>
        <translation>Vorschau &amp;&amp; Vergleich</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="85"/>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="119"/>
        <source>Models could not be written into the project&apos;s folder.</source>
        <translation>Modelle konnten nicht in den Projektordner geschrieben werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="122"/>
        <source>%1 was not applied: it would leave the project unsaveable (%2).</source>
        <translation>%1 wurde nicht ausgeführt: Das Projekt ließe sich danach nicht mehr speichern (%2).</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="134"/>
        <source>Playing without sound: %1.</source>
        <translation>Wiedergabe ohne Ton: %1.</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="140"/>
        <location filename="../studio/app/MainWindow.cpp" line="141"/>
        <source>No project open</source>
        <translation>Kein Projekt geöffnet</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="162"/>
        <source>Generated &amp;Face</source>
        <translation>Generiertes &amp;Gesicht</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="169"/>
        <source>&amp;Whole Face (Eyes Included)</source>
        <translation>&amp;Ganzes Gesicht (mit Augen)</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="171"/>
        <source>Synthesise the whole modelled face; otherwise the recording&apos;s own eyes and upper face are kept</source>
        <translation>Das ganze modellierte Gesicht synthetisieren; sonst bleiben die Augen und das Obergesicht der Aufnahme erhalten</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="164"/>
        <source>&amp;Synthesised Skin</source>
        <translation>&amp;Synthetisierte Haut</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="173"/>
        <source>&amp;Detail from Training Images</source>
        <translation>&amp;Details aus Trainingsbildern</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="175"/>
        <source>Add the teeth, lip highlights and skin detail of the AAM&apos;s nearest training images to the model&apos;s smooth texture</source>
        <translation>Zähne, Glanzlichter der Lippen und Hautdetails der nächstgelegenen Trainingsbilder des AAM zur glatten Textur des Modells hinzufügen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="177"/>
        <source>&amp;Match the Frame&apos;s Lighting</source>
        <translation>&amp;Beleuchtung an das Bild anpassen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="179"/>
        <source>Closed &amp;Lips from the Footage</source>
        <translation>Geschlossene Lippen aus dem &amp;Video</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="181"/>
        <source>Lips closed where the recording&apos;s are open are the person&apos;s own closed lips from another moment of the video; otherwise the AAM draws them</source>
        <translation>Wo die Aufnahme die Lippen offen hat, sind geschlossene Lippen die eigenen der Person aus einem anderen Moment des Videos; sonst zeichnet sie das AAM</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="183"/>
        <source>&amp;Open Mouths from the Footage</source>
        <translation>&amp;Offene Münder aus dem Filmmaterial</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="185"/>
        <source>The inside of a mouth opened wider than recorded (teeth, tongue) is the person&apos;s own open mouth from another moment of the video; otherwise the AAM draws it</source>
        <translation>Das Innere eines weiter als aufgenommen geöffneten Mundes (Zähne, Zunge) ist der eigene offene Mund der Person aus einem anderen Moment des Videos; sonst zeichnet es das AAM</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="205"/>
        <source>&amp;Close the Lips on /p b m/</source>
        <translation>&amp;Lippen bei /p b m/ schließen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="207"/>
        <source>Close the generated lips on the bilabials /p b m/, as speakers do; off: the model&apos;s trajectory as generated</source>
        <translation>Die erzeugten Lippen bei den Bilabialen /p b m/ schließen, wie Sprecher es tun; aus: die Trajektorie des Modells, wie sie erzeugt wurde</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="253"/>
        <source>Sequences</source>
        <translation>Sequenzen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="257"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="267"/>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="271"/>
        <source>Models</source>
        <translation>Modelle</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="292"/>
        <source>AAM: %1 · Models: %2</source>
        <translation>AAM: %1 · Modelle: %2</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="293"/>
        <source>none</source>
        <translation>keines</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="294"/>
        <source>none trained</source>
        <translation>keine trainiert</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="296"/>
        <source>The appearance model and the dynamic models the project uses now</source>
        <translation>Das Erscheinungsmodell und die dynamischen Modelle, die das Projekt jetzt verwendet</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="327"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="328"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="347"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="359"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="370"/>
        <source>&amp;Live: Speak and Watch the Face</source>
        <translation>&amp;Live: Sprechen und das Gesicht beobachten</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="372"/>
        <source>Speak into the microphone and watch the face move</source>
        <translation>Ins Mikrofon sprechen und dem Gesicht beim Bewegen zusehen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="376"/>
        <source>&amp;Panels</source>
        <translation>&amp;Bereiche</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="380"/>
        <source>&amp;Reset Layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="384"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="385"/>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="388"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="397"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="417"/>
        <source>Select a sequence</source>
        <translation>Wählen Sie eine Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="116"/>
        <source>The media of this sequence could not be read.</source>
        <translation>Die Mediendatei dieser Sequenz konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="166"/>
        <source>Paste the AAM&apos;s synthesis of the lower face, skin included; otherwise the recording&apos;s own lower face is moved to the generated lips&apos; opening and width and only the inside of the mouth is drawn</source>
        <translation>Die AAM-Synthese des unteren Gesichts samt Haut einsetzen; sonst wird das eigene untere Gesicht der Aufnahme auf die erzeugte Öffnung und Breite der Lippen bewegt und nur das Mundinnere gezeichnet</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="464"/>
        <source>Sound only: no video to show</source>
        <translation>Nur Ton: kein Video zu zeigen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="466"/>
        <source>The video has no frames</source>
        <translation>Das Video enthält keine Bilder</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/app/MainWindow.cpp" line="475"/>
        <source>%1: %n frames at %2 fps</source>
        <translation>
            <numerusform>%1: %n Bild mit %2 fps</numerusform>
            <numerusform>%1: %n Bilder mit %2 fps</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="484"/>
        <source>Audio energy of %1</source>
        <translation>Audioenergie von %1</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="485"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="485"/>
        <source>RMS per video frame</source>
        <translation>RMS je Videobild</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="491"/>
        <source>RMS</source>
        <translation>RMS</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="504"/>
        <source>%1 — frame %2 of %3</source>
        <translation>%1 – Bild %2 von %3</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="512"/>
        <location filename="../studio/app/MainWindow.cpp" line="520"/>
        <source>LipSync Studio</source>
        <translation>LipSync Studio</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="519"/>
        <source> (bundled demo, read-only)</source>
        <translation> (mitgeliefertes Demo, schreibgeschützt)</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="266"/>
        <source>Audio</source>
        <translation>Audio</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::MicrophoneInput</name>
    <message>
        <location filename="../studio/live/MicrophoneInput.cpp" line="21"/>
        <source>no microphone was chosen</source>
        <translation>es wurde kein Mikrofon gewählt</translation>
    </message>
    <message>
        <location filename="../studio/live/MicrophoneInput.cpp" line="31"/>
        <source>the microphone %1 offers no sound format the studio can read</source>
        <translation>das Mikrofon %1 bietet kein Tonformat, das das Studio lesen kann</translation>
    </message>
    <message>
        <location filename="../studio/live/MicrophoneInput.cpp" line="39"/>
        <source>the microphone %1 could not be opened</source>
        <translation>das Mikrofon %1 konnte nicht geöffnet werden</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ModelsPanel</name>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="61"/>
        <source>Appearance model</source>
        <translation>Erscheinungsmodell</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="62"/>
        <source>Phoneme aligner</source>
        <translation>Phonem-Aligner</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="152"/>
        <source>Build AAM…</source>
        <translation>AAM erstellen …</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="175"/>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="175"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="175"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="301"/>
        <source>Made in this session; written when the project is saved</source>
        <translation>In dieser Sitzung erstellt; wird beim Speichern des Projekts geschrieben</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="313"/>
        <source>No models yet</source>
        <translation>Noch keine Modelle</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="153"/>
        <source>Train</source>
        <translation>Trainieren</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="72"/>
        <source>%1 states for phones in context</source>
        <translation>%1 Zustände für Phoneme im Kontext</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="73"/>
        <source>one state per phone</source>
        <translation>ein Zustand je Phonem</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="76"/>
        <source>%1, full covariances</source>
        <translation>%1, volle Kovarianzen</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="78"/>
        <source>%1 parameters, %2, variance compensation</source>
        <translation>%1 Parameter, %2, Varianzkompensation</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="79"/>
        <source>%1 parameters, %2</source>
        <translation>%1 Parameter, %2</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="135"/>
        <source>For a person with little footage: HMM-mean&apos;s and Brand&apos;s mouth for each sound starts from the mouths of other speakers (GRID s1), carried onto this face, and moves to the person&apos;s own as their frames of that sound add up; how much the other speakers weigh is chosen on the person&apos;s own clips. Used by Train and Realism.</source>
        <translation>Für eine Person mit wenig Material: Der Mund von HMM-Mittelwert und Brand beginnt für jeden Laut bei den Mündern anderer Sprecher (GRID s1), übertragen auf dieses Gesicht, und geht zum eigenen Mund der Person über, je mehr Bilder sie von diesem Laut hat; wie viel die anderen Sprecher wiegen, wird an den eigenen Clips der Person gewählt. Gilt für Trainieren und Realismus.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="153"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="154"/>
        <source>Evaluate (k-fold)</source>
        <translation>Evaluieren (k-fach)</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="154"/>
        <location filename="../studio/build/ModelsPanel.cpp" line="269"/>
        <source>Realism</source>
        <translation>Realismus</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="157"/>
        <source>Variance compensation</source>
        <translation>Varianzkompensation</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="158"/>
        <source>Phones in context</source>
        <translation>Phoneme im Kontext</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="159"/>
        <source>Paper&apos;s models</source>
        <translation>Modelle des Artikels</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="159"/>
        <source>Start from other speakers</source>
        <translation>Von anderen Sprechern ausgehen</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="90"/>
        <source>VarPro / Levenberg–Marquardt</source>
        <translation>VarPro / Levenberg–Marquardt</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="80"/>
        <source>%1, started from other speakers</source>
        <translation>%1, ausgehend von anderen Sprechern</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="91"/>
        <source>Gradient ascent (paper)</source>
        <translation>Gradientenaufstieg (Artikel)</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="92"/>
        <source>Diagonal A</source>
        <translation>Diagonales A</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="93"/>
        <source>Full A</source>
        <translation>Volles A</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="96"/>
        <source>Covariance by CV</source>
        <translation>Kovarianz per KV</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="97"/>
        <source>Diagonal covariance</source>
        <translation>Diagonale Kovarianz</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="98"/>
        <source>Full covariance</source>
        <translation>Volle Kovarianz</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="120"/>
        <source>Scale each model&apos;s generated trajectories to the spread of the training features: lips that open and close as much as the recording&apos;s, at the cost of a larger error per frame. Off: the paper&apos;s models exactly.</source>
        <translation>Skaliert die erzeugten Trajektorien jedes Modells auf die Streuung der Trainingsmerkmale: Lippen, die sich so weit öffnen und schließen wie in der Aufnahme, um den Preis eines größeren Fehlers je Bild. Aus: genau die Modelle des Artikels.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="128"/>
        <source>Train each model on states for phones in their context (the neighbouring phones and the part of the phone), tied by decision trees: lips that anticipate the next sound. Off: one state per phone, the paper&apos;s models exactly.</source>
        <translation>Jedes Modell auf Zuständen für Phoneme in ihrem Kontext trainieren (die benachbarten Phoneme und der Teil des Phonems), durch Entscheidungsbäume gebündelt: Lippen, die den nächsten Laut vorwegnehmen. Aus: ein Zustand je Phonem, genau die Modelle des Artikels.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="143"/>
        <source>Train and evaluate the paper&apos;s models exactly: no compensation or phones in context, Brand with diagonal covariances, the DPDS by the paper&apos;s Algorithm 1 and gradient ascent without the variance prior; Realism renders without lip closure, colour matching or exemplar detail.</source>
        <translation>Genau die Modelle des Artikels trainieren und evaluieren: keine Kompensation und keine Phone im Kontext, Brand mit diagonalen Kovarianzen, das DPDS mit Algorithmus 1 des Artikels und Gradientenanstieg ohne Varianz-Prior; Realismus rendert ohne Lippenschluss, Farbanpassung und Exemplar-Details.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="199"/>
        <source>folds: </source>
        <translation>Teilmengen (k-fach): </translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="209"/>
        <source>Build an Active Appearance Model from the labelled frames (Faces menu).</source>
        <translation>Ein Active Appearance Model aus den beschrifteten Bildern erstellen (Menü Gesichter).</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="210"/>
        <source>Train the checked models on every sequence with features and phonemes</source>
        <translation>Die angekreuzten Modelle auf allen Sequenzen mit Merkmalen und Phonemen trainieren</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="211"/>
        <source>Stop training or evaluation; the previous models stay</source>
        <translation>Training oder Evaluation abbrechen; die bisherigen Modelle bleiben</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="212"/>
        <source>k-fold cross-validation of the checked models (the paper&apos;s Figure 4)</source>
        <translation>k-fache Kreuzvalidierung der angekreuzten Modelle (Abbildung 4 des Artikels)</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="217"/>
        <source>Render the held-out sequences of the same folds into their recordings and measure the lips with dlib&apos;s landmarks: opening correlation, articulation, /p b m/ closures, lag, sharpness, seam</source>
        <translation>Die zurückgehaltenen Sequenzen derselben Folds in ihre Aufnahmen rendern und die Lippen mit dlibs Landmarken messen: Korrelation der Öffnung, Artikulation, Verschlüsse bei /p b m/, Versatz, Schärfe, Naht</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="245"/>
        <source>AAM parameter </source>
        <translation>AAM-Parameter </translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="246"/>
        <source>Which AAM parameter to plot over time</source>
        <translation>Welcher AAM-Parameter über die Zeit gezeigt wird</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="256"/>
        <source>Not evaluated yet: Evaluate (k-fold) in the Models panel draws the paper&apos;s Figure 4 for the checked models.</source>
        <translation>Noch nicht evaluiert: Evaluieren (k-fach) im Modelle-Panel zeichnet Abbildung 4 des Artikels für die gewählten Modelle.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="261"/>
        <source>Not measured yet: Realism in the Models panel renders held-out sequences and measures the lips on them.</source>
        <translation>Noch nicht gemessen: Realismus im Modelle-Panel rendert zurückgehaltene Sequenzen und misst die Lippen darauf.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="266"/>
        <source>Trajectory</source>
        <translation>Trajektorie</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="267"/>
        <source>Training</source>
        <translation>Training</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="268"/>
        <source>Evaluation</source>
        <translation>Evaluation</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="349"/>
        <source>No sequence has both features and phonemes (%1 without features, %2 without phonemes): track the faces and align the speech first.</source>
        <translation>Keine Sequenz hat sowohl Merkmale als auch Phoneme (%1 ohne Merkmale, %2 ohne Phoneme): zuerst die Gesichter tracken und die Sprache alignieren.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="410"/>
        <source>Cannot start from other speakers: %1</source>
        <translation>Kann nicht von anderen Sprechern ausgehen: %1</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="420"/>
        <source>%1 of %2 phones never occur in the footage: their face comes from other speakers&apos; mouths</source>
        <translation>%1 von %2 Phonen kommen im Material nie vor: ihr Gesicht stammt von den Mündern anderer Sprecher</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="422"/>
        <source>%1 of %2 phones never occur in the footage: their face is guessed from the average</source>
        <translation>%1 von %2 Phonen kommen im Material nie vor: ihr Gesicht wird aus dem Durchschnitt geschätzt</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="426"/>
        <source>%1 have fewer than %2 frames</source>
        <translation>%1 haben weniger als %2 Bilder</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="428"/>
        <source>Phones in context made no context states: too little footage for them</source>
        <translation>Phone im Kontext haben keine Kontextzustände gebildet: zu wenig Material dafür</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="432"/>
        <source>More footage of the person (%1 s of speech now) covers more.</source>
        <translation>Mehr Material der Person (jetzt %1 s Sprache) deckt mehr ab.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="434"/>
        <source>Tick Start from other speakers to take the phones it lacks from other people&apos;s mouths.</source>
        <translation>Mit „Von anderen Sprechern ausgehen“ kommen die fehlenden Phone von den Mündern anderer Menschen.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="458"/>
        <source>Cannot start from other speakers without the project&apos;s AAM.</source>
        <translation>Ohne das AAM des Projekts kann nicht von anderen Sprechern ausgegangen werden.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="489"/>
        <location filename="../studio/build/ModelsPanel.cpp" line="533"/>
        <source>Train %1</source>
        <translation>%1 trainieren</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/build/ModelsPanel.cpp" line="491"/>
        <source>Training %1 on %n sequence(s)…</source>
        <translation>
            <numerusform>%1 wird auf %n Sequenz trainiert …</numerusform>
            <numerusform>%1 wird auf %n Sequenzen trainiert …</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="521"/>
        <source>%1 trained in %2 s: log-likelihood %3 nats/frame</source>
        <translation>%1 in %2 s trainiert: Log-Likelihood %3 nats/Bild</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="544"/>
        <source>Training %1 canceled: the previous model stays.</source>
        <translation>Training von %1 abgebrochen: das bisherige Modell bleibt.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="546"/>
        <source>Training %1 failed: %2</source>
        <translation>Training von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="553"/>
        <source>Check at least one model kind to train.</source>
        <translation>Mindestens eine Modellart zum Trainieren ankreuzen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/build/ModelsPanel.cpp" line="572"/>
        <source>Evaluated %n model(s) on %1 sequences, %2 folds: mean and 95 % interval over the folds.</source>
        <translation>
            <numerusform>%n Modell auf %1 Sequenzen evaluiert, %2 Teilmengen: Mittelwert und 95-%-Intervall über die Teilmengen.</numerusform>
            <numerusform>%n Modelle auf %1 Sequenzen evaluiert, %2 Teilmengen: Mittelwert und 95-%-Intervall über die Teilmengen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="635"/>
        <source>Check at least one model kind to evaluate.</source>
        <translation>Mindestens eine Modellart zum Evaluieren ankreuzen.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="636"/>
        <source>Cross-validation needs at least two sequences.</source>
        <translation>Die Kreuzvalidierung braucht mindestens zwei Sequenzen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/build/ModelsPanel.cpp" line="567"/>
        <source>Evaluate %n model(s) (%1-fold)</source>
        <translation>
            <numerusform>%n Modell evaluieren (%1-fach)</numerusform>
            <numerusform>%n Modelle evaluieren (%1-fach)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="100"/>
        <source>Brand&apos;s output covariances. By CV: diagonal or full, whichever of the two generates held-out training sequences more closely (cross-validation). Diagonal: the paper&apos;s model.</source>
        <translation>Brands Ausgabekovarianzen. Per KV: diagonal oder voll, je nachdem, welche der beiden zurückgehaltene Trainingssequenzen genauer erzeugt (Kreuzvalidierung). Diagonal: das Modell der Veröffentlichung.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/build/ModelsPanel.cpp" line="604"/>
        <source>Realism of %n model(s) (%1-fold)</source>
        <translation>
            <numerusform>Realismus von %n Modell (%1 Folds)</numerusform>
            <numerusform>Realismus von %n Modellen (%1 Folds)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/build/ModelsPanel.cpp" line="609"/>
        <source>Rendered %1 held-out sequences (%2 folds) and measured the lips with dlib&apos;s landmarks: the AAM&apos;s re-synthesis and %n model(s).</source>
        <translation>
            <numerusform>%1 zurückgehaltene Sequenzen (%2 Folds) gerendert und die Lippen mit dlibs Landmarken gemessen: die Resynthese des AAM und %n Modell.</numerusform>
            <numerusform>%1 zurückgehaltene Sequenzen (%2 Folds) gerendert und die Lippen mit dlibs Landmarken gemessen: die Resynthese des AAM und %n Modelle.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="664"/>
        <source>Evaluation failed: %1</source>
        <translation>Evaluation fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="665"/>
        <source>Failed: %1.</source>
        <translation>Fehlgeschlagen: %1.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="667"/>
        <source>Canceled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="698"/>
        <source>A model of this project could not be loaded.</source>
        <translation>Ein Modell dieses Projekts konnte nicht geladen werden.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="703"/>
        <source>Some models could not be loaded: %1</source>
        <translation>Einige Modelle konnten nicht geladen werden: %1</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="530"/>
        <source>The %1 model could not be saved: %2</source>
        <translation>Das Modell %1 konnte nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="727"/>
        <source>%1: no features yet (track the faces first)</source>
        <translation>%1: noch keine Merkmale (zuerst die Gesichter tracken)</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="737"/>
        <source>real</source>
        <translation>echt</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="751"/>
        <source>%1 — AAM parameter %2</source>
        <translation>%1 — AAM-Parameter %2</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ModesView</name>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="28"/>
        <source>AAM Modes of Variation</source>
        <translation>Variationsmoden des AAM</translation>
    </message>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="40"/>
        <source>Combined mode %1, -3 to +3 standard deviations</source>
        <translation>Kombinierte Mode %1, −3 bis +3 Standardabweichungen</translation>
    </message>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="43"/>
        <source>Mode %1</source>
        <translation>Mode %1</translation>
    </message>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="51"/>
        <source>&amp;Reset to Mean</source>
        <translation>Auf &amp;Mittelwert zurücksetzen</translation>
    </message>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="93"/>
        <source>%1 s.d.</source>
        <translation>%1 SA</translation>
    </message>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="97"/>
        <source>No AAM yet: label frames and choose Faces ▸ Build AAM.</source>
        <translation>Noch kein AAM: Bilder beschriften und Gesichter ▸ AAM erstellen wählen.</translation>
    </message>
    <message>
        <location filename="../studio/build/ModesView.cpp" line="101"/>
        <source>%1 training frames, %2 shape, %3 texture and %4 combined modes.</source>
        <translation>%1 Trainingsbilder, %2 Form-, %3 Textur- und %4 kombinierte Moden.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::MouthShapesDialog</name>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="58"/>
        <source>Closed, lips pressed: P, B, M</source>
        <translation>Geschlossen, Lippen aufeinander: P, B, M</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="59"/>
        <source>Slightly open, teeth clenched: K, S, T, EE</source>
        <translation>Leicht offen, Zähne zusammen: K, S, T, EE</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="60"/>
        <source>Open: EH as in men, AE as in bat</source>
        <translation>Offen: EH wie in men, AE wie in bat</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="61"/>
        <source>Wide open: AA as in father</source>
        <translation>Weit offen: AA wie in father</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="62"/>
        <source>Slightly rounded: AO as in off, ER as in bird</source>
        <translation>Leicht gerundet: AO wie in off, ER wie in bird</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="63"/>
        <source>Puckered: UW as in you, OW as in show, W</source>
        <translation>Gespitzt: UW wie in you, OW wie in show, W</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="64"/>
        <source>Upper teeth on the lower lip: F, V</source>
        <translation>Obere Zähne auf der Unterlippe: F, V</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="65"/>
        <source>Tongue raised behind the teeth: long L</source>
        <translation>Zunge hinter den Zähnen gehoben: langes L</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="66"/>
        <source>Rest, in every pause</source>
        <translation>Ruhe, in jeder Pause</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="76"/>
        <source>Mouth Shapes</source>
        <translation>Mundbilder</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="79"/>
        <source>&lt;b&gt;Shape&lt;/b&gt;</source>
        <translation>&lt;b&gt;Mundbild&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="80"/>
        <source>&lt;b&gt;Taught by&lt;/b&gt;</source>
        <translation>&lt;b&gt;Quelle&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="103"/>
        <source>%1 of shape %2, from 0 to 1 over this person&apos;s range</source>
        <translation>%1 von Mundbild %2, von 0 bis 1 über den Bereich dieser Person</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="110"/>
        <source>Set Mouth Shape %1</source>
        <translation>Mundbild %1 festlegen</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="115"/>
        <source>From Frame</source>
        <translation>Aus Bild</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="116"/>
        <source>Make shape %1 the mouth of the frame shown in the studio</source>
        <translation>Mundbild %1 als Mund des im Studio gezeigten Bildes festlegen</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="117"/>
        <source>Learned</source>
        <translation>Gelernt</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="118"/>
        <source>Use the shape learned from this person&apos;s frames again</source>
        <translation>Wieder das aus den Bildern dieser Person gelernte Mundbild verwenden</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="126"/>
        <source>Reset Mouth Shape %1</source>
        <translation>Mundbild %1 zurücksetzen</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="133"/>
        <source>Learn Again</source>
        <translation>Neu lernen</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="134"/>
        <source>Measure the project&apos;s tracked, aligned frames again</source>
        <translation>Die verfolgten, ausgerichteten Bilder des Projekts neu messen</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="149"/>
        <source>Silence is always X and /p b m/ always A; the other frames take the shape they look most like, their phone&apos;s shape first. Shapes you set are kept with the project.</source>
        <translation>Stille ist immer X und /p b m/ immer A; die übrigen Bilder bekommen das Mundbild, dem sie am ähnlichsten sehen, das ihres Lauts zuerst. Festgelegte Mundbilder werden mit dem Projekt gespeichert.</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="194"/>
        <source>The project has no AAM yet: build one in the Models panel, then track and align its sequences.</source>
        <translation>Das Projekt hat noch kein AAM: im Modelle-Bereich erstellen, dann seine Sequenzen verfolgen und ausrichten.</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="201"/>
        <source>Learning this person&apos;s mouth shapes…</source>
        <translation>Die Mundbilder dieser Person werden gelernt…</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="204"/>
        <source>Learn the mouth shapes</source>
        <translation>Mundbilder lernen</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="217"/>
        <source>Not learned: %1. Track and align more of the project.</source>
        <translation>Nicht gelernt: %1. Mehr vom Projekt verfolgen und ausrichten.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/export/MouthShapesDialog.cpp" line="227"/>
        <source>Learned from %n frames</source>
        <translation>
            <numerusform>Gelernt aus %n Bild</numerusform>
            <numerusform>Gelernt aus %n Bildern</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/export/MouthShapesDialog.cpp" line="228"/>
        <source> of %n tracked, aligned sequences.</source>
        <translation>
            <numerusform> von %n verfolgten, ausgerichteten Sequenz.</numerusform>
            <numerusform> von %n verfolgten, ausgerichteten Sequenzen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="260"/>
        <source>you</source>
        <translation>von Ihnen</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/export/MouthShapesDialog.cpp" line="261"/>
        <source>%n frames</source>
        <translation>
            <numerusform>%n Bild</numerusform>
            <numerusform>%n Bilder</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="262"/>
        <source>a drawing (no frames)</source>
        <translation>eine Zeichnung (keine Bilder)</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="314"/>
        <source>The frame shown has no face features: choose a tracked sequence&apos;s frame first.</source>
        <translation>Das gezeigte Bild hat keine Gesichtsmerkmale: zuerst ein Bild einer verfolgten Sequenz wählen.</translation>
    </message>
    <message>
        <location filename="../studio/export/MouthShapesDialog.cpp" line="319"/>
        <source>Mouth Shape %1 from Frame %2</source>
        <translation>Mundbild %1 aus Bild %2</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ObjectivePlot</name>
    <message>
        <location filename="../studio/plots/ObjectivePlot.cpp" line="7"/>
        <source>Training objective</source>
        <translation>Trainingsziel</translation>
    </message>
    <message>
        <location filename="../studio/plots/ObjectivePlot.cpp" line="8"/>
        <source>iteration</source>
        <translation>Iteration</translation>
    </message>
    <message>
        <location filename="../studio/plots/ObjectivePlot.cpp" line="8"/>
        <source>objective</source>
        <translation>Zielfunktion</translation>
    </message>
    <message>
        <location filename="../studio/plots/ObjectivePlot.cpp" line="59"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ParticipantSession</name>
    <message>
        <location filename="../studio/compare/ParticipantSession.cpp" line="74"/>
        <source>Preparing study trial %1</source>
        <translation>Studiendurchgang %1 wird vorbereitet</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantSession.cpp" line="91"/>
        <source>This trial cannot be shown: %1</source>
        <translation>Dieser Durchgang kann nicht gezeigt werden: %1</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantSession.cpp" line="129"/>
        <source>Record the answer</source>
        <translation>Antwort speichern</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantSession.cpp" line="130"/>
        <source>The answer could not be saved. Please call the experimenter.</source>
        <translation>Die Antwort konnte nicht gespeichert werden. Bitte rufen Sie die Versuchsleitung.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ParticipantView</name>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="26"/>
        <source>Which one is real?</source>
        <translation>Welches ist echt?</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="56"/>
        <source>Preparing the next videos…</source>
        <translation>Die nächsten Videos werden vorbereitet …</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="57"/>
        <location filename="../studio/compare/ParticipantView.cpp" line="70"/>
        <source>Trial %1 of %2</source>
        <translation>Durchgang %1 von %2</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="71"/>
        <source>Which video is real?   ← left     ↓ can&apos;t decide     → right     R replay</source>
        <translation>Welches Video ist echt?   ← links     ↓ unentschieden     → rechts     R wiederholen</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="84"/>
        <source>Thank you! All answers are saved.</source>
        <translation>Vielen Dank! Alle Antworten sind gespeichert.</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="85"/>
        <location filename="../studio/compare/ParticipantView.cpp" line="94"/>
        <source>Press Esc to leave.</source>
        <translation>Esc drücken zum Verlassen.</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="172"/>
        <source>Leave the study</source>
        <translation>Studie verlassen</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="173"/>
        <source>Leave the study now? The answers given so far are saved; this participant can continue later.</source>
        <translation>Die Studie jetzt verlassen? Die bisherigen Antworten sind gespeichert; diese Person kann später weitermachen.</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="178"/>
        <source>Leave</source>
        <translation>Verlassen</translation>
    </message>
    <message>
        <location filename="../studio/compare/ParticipantView.cpp" line="179"/>
        <source>Continue the study</source>
        <translation>Studie fortsetzen</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::PlaybackController</name>
    <message>
        <location filename="../studio/context/PlaybackController.cpp" line="109"/>
        <source>no audio output device was found</source>
        <translation>kein Audio-Ausgabegerät gefunden</translation>
    </message>
    <message>
        <location filename="../studio/context/PlaybackController.cpp" line="118"/>
        <source>the audio device %1 takes neither float nor 16-bit samples</source>
        <translation>das Audiogerät %1 nimmt weder Float- noch 16-Bit-Samples an</translation>
    </message>
    <message>
        <location filename="../studio/context/PlaybackController.cpp" line="132"/>
        <source>the clip&apos;s sound could not be decoded</source>
        <translation>der Ton des Clips konnte nicht dekodiert werden</translation>
    </message>
    <message>
        <location filename="../studio/context/PlaybackController.cpp" line="170"/>
        <source>the audio device %1 could not be opened</source>
        <translation>das Audiogerät %1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../studio/context/PlaybackController.cpp" line="205"/>
        <source>the audio device stopped</source>
        <translation>das Audiogerät hat die Wiedergabe abgebrochen</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::PreviewPanel</name>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="68"/>
        <source>Loop selection</source>
        <translation>Auswahl wiederholen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="68"/>
        <source>Landmarks</source>
        <translation>Landmarken</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="69"/>
        <source>Generate from Speech…</source>
        <translation>Aus Sprache erzeugen…</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="70"/>
        <source>Back to Sequence</source>
        <translation>Zurück zur Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="83"/>
        <source>Previous frame</source>
        <translation>Vorheriges Bild</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="85"/>
        <source>Next frame</source>
        <translation>Nächstes Bild</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="89"/>
        <source>Scrub through the frames</source>
        <translation>Durch die Bilder fahren</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="90"/>
        <source>Play the timeline&apos;s selection (or everything) over and over</source>
        <translation>Die Auswahl der Zeitleiste (oder alles) immer wieder abspielen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="91"/>
        <source>Show the tracked points on the recorded video and the generated points on the generated faces</source>
        <translation>Die getrackten Punkte auf dem aufgenommenen Video und die erzeugten Punkte auf den erzeugten Gesichtern zeigen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="92"/>
        <source>Generate faces for any recording with a transcript</source>
        <translation>Gesichter für eine beliebige Aufnahme mit Transkript erzeugen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="93"/>
        <source>Show the current sequence again</source>
        <translation>Die aktuelle Sequenz wieder zeigen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="267"/>
        <source>Prepare the preview of %1</source>
        <translation>Vorschau von %1 vorbereiten</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="302"/>
        <source>The head could not be tracked: %1</source>
        <translation>Der Kopf konnte nicht getrackt werden: %1</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="341"/>
        <source>Recorded video (landmarks: tracked)</source>
        <translation>Aufgenommenes Video (Landmarken: getrackt)</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="346"/>
        <source>Generated: %1</source>
        <translation>Erzeugt: %1</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="350"/>
        <source>Generated</source>
        <translation>Erzeugt</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="401"/>
        <source>The project has no appearance model (Faces ▸ Build AAM).</source>
        <translation>Das Projekt hat kein Erscheinungsmodell (Gesichter ▸ AAM erstellen).</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="403"/>
        <source>Tracking the head pose…</source>
        <translation>Kopfhaltung wird getrackt…</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="405"/>
        <source>This sequence has no phones (align it in the Timeline).</source>
        <translation>Diese Sequenz hat keine Phoneme (in der Zeitleiste alignieren).</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="407"/>
        <source>Train a dynamic model in the Models panel to see the faces it generates.</source>
        <translation>Trainieren Sie ein dynamisches Modell im Bereich „Modelle“, um die erzeugten Gesichter zu sehen.</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="413"/>
        <source>Sound only: no video to show</source>
        <translation>Nur Ton: kein Video zu zeigen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="461"/>
        <source>%1 — frame %2 of %3</source>
        <translation>%1 — Bild %2 von %3</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="570"/>
        <source>Faces for new speech need the project&apos;s appearance model.</source>
        <translation>Gesichter für neue Sprache brauchen das Erscheinungsmodell des Projekts.</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="571"/>
        <source>Build one with Faces ▸ Build AAM.</source>
        <translation>Erstellen Sie eines mit Gesichter ▸ AAM erstellen.</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="576"/>
        <location filename="../studio/preview/PreviewPanel.cpp" line="630"/>
        <source>No faces could be generated for this speech.</source>
        <translation>Für diese Sprachaufnahme konnten keine Gesichter erzeugt werden.</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="577"/>
        <source>Train a dynamic model in the Models panel first.</source>
        <translation>Trainieren Sie zuerst ein dynamisches Modell im Bereich „Modelle“.</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="608"/>
        <source>Generate faces for %1</source>
        <translation>Gesichter für %1 erzeugen</translation>
    </message>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="645"/>
        <source>The words did not fit this voice with the timeline&apos;s aligner: aligned with CMU Sphinx&apos;s generic model adapted to the recording</source>
        <translation>Die Wörter passten mit dem Aligner der Zeitleiste nicht zu dieser Stimme: mit dem an die Aufnahme angepassten allgemeinen Modell von CMU Sphinx aligniert</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ProjectDocument</name>
    <message>
        <location filename="../studio/document/ProjectDocument.cpp" line="183"/>
        <source>the project already has a sequence %1</source>
        <translation>das Projekt hat bereits eine Sequenz %1</translation>
    </message>
    <message>
        <location filename="../studio/document/ProjectDocument.cpp" line="297"/>
        <source>%1 interval %2: %3</source>
        <translation>%1, Intervall %2: %3</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ProjectFiles</name>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="45"/>
        <source>Autosave failed (unsaved changes are only in memory; the project on disk is untouched): %1</source>
        <translation>Automatisches Speichern fehlgeschlagen (ungespeicherte Änderungen sind nur im Speicher; das Projekt auf der Festplatte ist unverändert): %1</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="56"/>
        <location filename="../studio/app/ProjectFiles.cpp" line="120"/>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="57"/>
        <source>LipSync projects (project.json)</source>
        <translation>LipSync-Projekte (project.json)</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="67"/>
        <source>New Project: the Folder of Your Clips (transcripts beside them)</source>
        <translation>Neues Projekt: der Ordner mit Ihren Clips (Transkripte daneben)</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="76"/>
        <location filename="../studio/app/ProjectFiles.cpp" line="108"/>
        <source>No new project was created.</source>
        <translation>Es wurde kein neues Projekt angelegt.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="77"/>
        <source>the folder already holds a project: open it instead</source>
        <translation>Der Ordner enthält bereits ein Projekt: Öffnen Sie es stattdessen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="80"/>
        <source>New project from %1</source>
        <translation>Neues Projekt aus %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/app/ProjectFiles.cpp" line="100"/>
        <source>%n clip(s) could not be read and were left out.</source>
        <translation>
            <numerusform>%n Clip konnte nicht gelesen werden und wurde ausgelassen.</numerusform>
            <numerusform>%n Clips konnten nicht gelesen werden und wurden ausgelassen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="121"/>
        <source>%1 holds no project. Create a new project from the clips in it?</source>
        <translation>%1 enthält kein Projekt. Ein neues Projekt aus den Clips darin anlegen?</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="129"/>
        <source>The project could not be opened.</source>
        <translation>Das Projekt konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="159"/>
        <source>The bundled demo project was not found.</source>
        <translation>Das mitgelieferte Demoprojekt wurde nicht gefunden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="160"/>
        <source>Looked for demo/ in: %1</source>
        <translation>demo/ gesucht in: %1</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="167"/>
        <source>The demo project could not be opened.</source>
        <translation>Das Demoprojekt konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="192"/>
        <source>Save Project As (a folder)</source>
        <translation>Projekt speichern unter (ein Ordner)</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="197"/>
        <location filename="../studio/app/ProjectFiles.cpp" line="216"/>
        <source>The project could not be saved.</source>
        <translation>Das Projekt konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="198"/>
        <source>a file of that name exists; a project needs a folder</source>
        <translation>es gibt eine Datei dieses Namens; ein Projekt braucht einen Ordner</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="203"/>
        <source>Replace Project</source>
        <translation>Projekt ersetzen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="204"/>
        <source>%1 already holds a project. Replace it?</source>
        <translation>%1 enthält bereits ein Projekt. Ersetzen?</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="229"/>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="229"/>
        <source>The project has unsaved changes. Save them?</source>
        <translation>Das Projekt hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::PronunciationsDialog</name>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="22"/>
        <source>Set</source>
        <translation>Festlegen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="23"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="25"/>
        <source>Pronunciations</source>
        <translation>Aussprachen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="27"/>
        <source>Words are pronounced from this list first, then from the CMU dictionary, then guessed by espeak-ng. Phones are ARPAbet (AA … ZH, sil, br).</source>
        <translation>Wörter werden zuerst nach dieser Liste ausgesprochen, dann nach dem CMU-Wörterbuch, sonst von espeak-ng geschätzt. Phone sind ARPAbet (AA … ZH, sil, br).</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="32"/>
        <source>Word</source>
        <translation>Wort</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="32"/>
        <source>Phones</source>
        <translation>Phone</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="32"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="41"/>
        <source>word</source>
        <translation>Wort</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="42"/>
        <source>e.g. L IH P S IH NG K</source>
        <translation>z. B. L IH P S IH NG K</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="43"/>
        <source>Word:</source>
        <translation>Wort:</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="44"/>
        <source>Phones:</source>
        <translation>Phone:</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="85"/>
        <source>Enter one word.</source>
        <translation>Geben Sie ein Wort ein.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="97"/>
        <source>&apos;%1&apos; is not one of the 41 phones (ARPAbet AA … ZH, sil, br).</source>
        <translation>„%1“ ist keines der 41 Phone (ARPAbet AA … ZH, sil, br).</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="105"/>
        <source>Enter the phones of the word.</source>
        <translation>Geben Sie die Phone des Wortes ein.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="121"/>
        <source>Set Pronunciation of %1</source>
        <translation>Aussprache von %1 festlegen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="122"/>
        <source>No change.</source>
        <translation>Keine Änderung.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="125"/>
        <source>&apos;%1&apos; is pronounced %2 in this project.</source>
        <translation>„%1“ wird in diesem Projekt %2 ausgesprochen.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="135"/>
        <source>The project has no pronunciation for &apos;%1&apos;.</source>
        <translation>Das Projekt hat keine Aussprache für „%1“.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="138"/>
        <source>Remove Pronunciation of %1</source>
        <translation>Aussprache von %1 entfernen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="166"/>
        <source>project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location filename="../studio/timeline/PronunciationsDialog.cpp" line="169"/>
        <source>espeak-ng guess</source>
        <translation>Schätzung von espeak-ng</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::RecentProjects</name>
    <message>
        <location filename="../studio/app/RecentProjects.cpp" line="71"/>
        <source>No recent projects</source>
        <translation>Keine zuletzt geöffneten Projekte</translation>
    </message>
    <message>
        <location filename="../studio/app/RecentProjects.cpp" line="75"/>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ResultsPage</name>
    <message>
        <location filename="../studio/plots/ResultsPage.cpp" line="63"/>
        <source>Computing: %1…</source>
        <translation>Berechnung: %1…</translation>
    </message>
    <message>
        <location filename="../studio/plots/ResultsPage.cpp" line="64"/>
        <source>Computing: %1… (shown until then: %2)</source>
        <translation>Berechnung: %1… (bis dahin angezeigt: %2)</translation>
    </message>
    <message>
        <location filename="../studio/plots/ResultsPage.cpp" line="70"/>
        <source>%1 Shown: %2</source>
        <translation>%1 Angezeigt: %2</translation>
    </message>
    <message>
        <location filename="../studio/plots/ResultsPage.cpp" line="167"/>
        <source>%1, %2: mean %3 over %4 folds, 95 % interval ± %5</source>
        <translation>%1, %2: Mittelwert %3 über %4 Teilmengen, 95-%-Intervall ± %5</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ScreenshotRunner</name>
    <message>
        <location filename="../studio/app/ScreenshotRunner.cpp" line="34"/>
        <source>lipsync-studio: timed out waiting for the project to load</source>
        <translation>lipsync-studio: Zeitüberschreitung beim Laden des Projekts</translation>
    </message>
    <message>
        <location filename="../studio/app/ScreenshotRunner.cpp" line="58"/>
        <source>lipsync-studio: cannot write %1</source>
        <translation>lipsync-studio: %1 kann nicht geschrieben werden</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::SequenceDetailsView</name>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="31"/>
        <source>Media:</source>
        <translation>Medien:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="32"/>
        <source>Video:</source>
        <translation>Video:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="33"/>
        <source>Audio:</source>
        <translation>Audio:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="35"/>
        <source>Transcript:</source>
        <translation>Transkript:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="36"/>
        <source>Words:</source>
        <translation>Wörter:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="37"/>
        <source>Landmarks:</source>
        <translation>Landmarken:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="43"/>
        <source>No sequence</source>
        <translation>Keine Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="57"/>
        <source>sound only, %1 frames at %2 fps</source>
        <translation>nur Ton, %1 Bilder mit %2 fps</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="61"/>
        <source>%1 frames, %2 fps, %3×%4</source>
        <translation>%1 Bilder, %2 fps, %3×%4</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="67"/>
        <source>%1 s, decoded at %2 Hz mono</source>
        <translation>%1 s, dekodiert mit %2 Hz mono</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="71"/>
        <source>none (%1)</source>
        <translation>keiner (%1)</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="75"/>
        <source>none</source>
        <translation>keines</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="76"/>
        <source>%1 words; does not fit the sound</source>
        <translation>%1 Wörter; passt nicht zum Ton</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="77"/>
        <source>proposed, not checked</source>
        <translation>vorgeschlagen, nicht geprüft</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="78"/>
        <source>%1 words</source>
        <translation>%1 Wörter</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="82"/>
        <source>Its alignment found other words in the sound (%1 nats per frame, below %2): check the transcript, then align the sequence again</source>
        <translation>Die Alignierung hat andere Wörter im Ton gefunden (%1 nats pro Frame, unter %2): Transkript prüfen, dann die Sequenz neu alignieren</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="86"/>
        <source>Proposed by speech recognition: edit it in the list&apos;s Transcript column, or accept it as it is</source>
        <translation>Von der Spracherkennung vorgeschlagen: in der Spalte Transkript der Liste bearbeiten oder so übernehmen, wie es ist</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="92"/>
        <source>%1 timed words</source>
        <translation>%1 Wörter mit Zeitangaben</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="93"/>
        <source>%1 of %2 frames</source>
        <translation>%1 von %2 Bildern</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::SequenceListModel</name>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="54"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="75"/>
        <source>The transcript does not fit the sound (%1 nats per frame against the aligner&apos;s best phones, below %2): these are likely not the clip&apos;s words. Check them, then align the sequence again. An aligner that does not know the speaker scores every transcript low: then align with the project&apos;s own aligner, or Generic US English with Adapt to Speaker.</source>
        <translation>Das Transkript passt nicht zum Ton (%1 nats pro Frame gegenüber den besten Phonen des Aligners, unter %2): Vermutlich sind es nicht die Wörter dieses Clips. Prüfen Sie sie und alignieren Sie die Sequenz neu. Ein Aligner, der den Sprecher nicht kennt, bewertet jedes Transkript niedrig: Alignieren Sie dann mit dem eigenen Aligner des Projekts oder mit Allgemeines US-Englisch und An Sprecher anpassen.</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="82"/>
        <source>Proposed by speech recognition and not checked yet: double-click to edit it, or accept it as it is (Accept Proposed Transcript, in the Edit menu or on right-click)</source>
        <translation>Von der Spracherkennung vorgeschlagen und noch nicht geprüft: doppelklicken, um es zu bearbeiten, oder so übernehmen, wie es ist (Vorgeschlagenes Transkript übernehmen, im Menü Bearbeiten oder per Rechtsklick)</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="86"/>
        <source>Doubtful words, the most doubtful first: %1</source>
        <translation>Unsichere Wörter, die unsichersten zuerst: %1</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="90"/>
        <source>Double-click to edit the transcript</source>
        <translation>Doppelklicken, um das Transkript zu bearbeiten</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="91"/>
        <source>%1 — %2 frames at %3 fps</source>
        <translation>%1 – %2 Bilder mit %3 fps</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="131"/>
        <source>Sequence</source>
        <translation>Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="132"/>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="133"/>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="134"/>
        <source>Transcript</source>
        <translation>Transkript</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ShortcutsDialog</name>
    <message>
        <location filename="../studio/app/ShortcutsDialog.cpp" line="83"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../studio/app/ShortcutsDialog.cpp" line="85"/>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <location filename="../studio/app/ShortcutsDialog.cpp" line="85"/>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::SpeakerAlignerTrainer</name>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="111"/>
        <source>Train the Speaker&apos;s Own Aligner…</source>
        <translation>Eigenes Ausrichtungsmodell des Sprechers trainieren…</translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="117"/>
        <source>Train an aligner model on this project&apos;s transcribed speech (three minutes of words or more), and align the project with it from then on</source>
        <translation>Ein Ausrichtungsmodell auf der transkribierten Sprache dieses Projekts trainieren (drei Minuten Wörter oder mehr) und das Projekt fortan damit ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="143"/>
        <source> Its %1 min of words can train the speaker&apos;s own aligner: Model ▸ Train the Speaker&apos;s Own Aligner…</source>
        <translation> Seine %1 min Wörter reichen, um ein eigenes Ausrichtungsmodell des Sprechers zu trainieren: Modell ▸ Eigenes Ausrichtungsmodell des Sprechers trainieren…</translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="151"/>
        <source>Train the Speaker&apos;s Own Aligner</source>
        <translation>Eigenes Ausrichtungsmodell des Sprechers trainieren</translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="159"/>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="207"/>
        <source>The aligner could not be trained.</source>
        <translation>Das Ausrichtungsmodell konnte nicht trainiert werden.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="160"/>
        <source>The model is written into the project&apos;s folder, and the bundled demo is read-only: save the project in a folder of your own first.</source>
        <translation>Das Modell wird in den Projektordner geschrieben, und die mitgelieferte Demo ist schreibgeschützt: speichern Sie das Projekt zuerst in einem eigenen Ordner.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="211"/>
        <source>Trained on %1</source>
        <translation>Auf %1 trainiert</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="214"/>
        <source>The speaker&apos;s own aligner is trained on %n sequences</source>
        <translation>
            <numerusform>Das eigene Ausrichtungsmodell des Sprechers ist auf %n Sequenz trainiert</numerusform>
            <numerusform>Das eigene Ausrichtungsmodell des Sprechers ist auf %n Sequenzen trainiert</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/timeline/SpeakerAlignerTrainer.cpp" line="215"/>
        <source> (%1 min of words). On %2 sequences it was not trained on, %3 % of its word boundaries are within 40 ms of the project&apos;s timings. The project is aligned with it from now on.</source>
        <translation> (%1 min Wörter). Auf %2 Sequenzen, auf denen es nicht trainiert wurde, liegen %3 % seiner Wortgrenzen innerhalb von 40 ms der Zeiten des Projekts. Das Projekt wird fortan damit ausgerichtet.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::SpeechDialog</name>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="28"/>
        <source>Generate from Speech</source>
        <translation>Aus Sprache erzeugen</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="30"/>
        <source>Faces for any recording with a transcript: the speech is aligned to its words, labelled per frame and given to a trained dynamic model.</source>
        <translation>Gesichter für jede Aufnahme mit Transkript: Die Sprache wird an ihre Wörter ausgerichtet, pro Bild etikettiert und einem trainierten dynamischen Modell übergeben.</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="38"/>
        <source>An audio or video file</source>
        <translation>Eine Audio- oder Videodatei</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="39"/>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="42"/>
        <source>Speech:</source>
        <translation>Sprache:</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="43"/>
        <source>The words spoken, e.g. &quot;bin blue at f two now&quot;</source>
        <translation>Die gesprochenen Wörter, z. B. „bin blue at f two now“</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="46"/>
        <source>Transcript:</source>
        <translation>Transkript:</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="49"/>
        <source> fps</source>
        <translation> B/s</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="51"/>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="54"/>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="58"/>
        <source>Generate</source>
        <translation>Erzeugen</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="117"/>
        <source>Choose Speech</source>
        <translation>Sprachaufnahme wählen</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="118"/>
        <source>Audio and video (*.wav *.flac *.mp3 *.ogg *.m4a *.mpg *.mp4 *.mov *.avi *.mkv *.webm);;All files (*)</source>
        <translation>Audio und Video (*.wav *.flac *.mp3 *.ogg *.m4a *.mpg *.mp4 *.mov *.avi *.mkv *.webm);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="127"/>
        <source>Train a dynamic model in the Models panel first.</source>
        <translation>Trainieren Sie zuerst ein dynamisches Modell im Bereich „Modelle“.</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="129"/>
        <source>Choose an audio or video file.</source>
        <translation>Wählen Sie eine Audio- oder Videodatei.</translation>
    </message>
    <message>
        <location filename="../studio/preview/SpeechDialog.cpp" line="131"/>
        <source>Type the words spoken (no transcript file was found beside it).</source>
        <translation>Geben Sie die gesprochenen Wörter ein (daneben wurde keine Transkriptdatei gefunden).</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::StudioContext</name>
    <message>
        <location filename="../studio/context/StudioContext.cpp" line="74"/>
        <source>Loading %1…</source>
        <translation>%1 wird geladen …</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::StudyController</name>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="24"/>
        <source>&amp;Study</source>
        <translation>&amp;Studie</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="25"/>
        <source>&amp;Set Up Study…</source>
        <translation>Studie &amp;einrichten …</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="25"/>
        <source>&amp;Run Participant…</source>
        <translation>&amp;Teilnehmende Person starten …</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="26"/>
        <source>Study &amp;Results</source>
        <translation>Studien&amp;ergebnisse</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="83"/>
        <location filename="../studio/compare/StudyController.cpp" line="94"/>
        <source>Set up study</source>
        <translation>Studie einrichten</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/compare/StudyController.cpp" line="84"/>
        <source>The current study has %n answer(s). Replace it with a new study? (Edit ▸ Undo brings it back.)</source>
        <translation>
            <numerusform>Die aktuelle Studie hat %n Antwort(en). Durch eine neue Studie ersetzen? (Bearbeiten ▸ Rückgängig holt sie zurück.)</numerusform>
            <numerusform>Die aktuelle Studie hat %n Antwort(en). Durch eine neue Studie ersetzen? (Bearbeiten ▸ Rückgängig holt sie zurück.)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="105"/>
        <location filename="../studio/compare/StudyController.cpp" line="119"/>
        <location filename="../studio/compare/StudyController.cpp" line="135"/>
        <location filename="../studio/compare/StudyController.cpp" line="164"/>
        <source>Run participant</source>
        <translation>Teilnehmende Person starten</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="106"/>
        <source>The project must be saved with the study before a participant starts (every answer is saved at once). Save now?</source>
        <translation>Das Projekt muss mit der Studie gespeichert sein, bevor eine Person beginnt (jede Antwort wird sofort gespeichert). Jetzt speichern?</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="119"/>
        <source>The project has no study yet.</source>
        <translation>Das Projekt hat noch keine Studie.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="152"/>
        <source>New participant: %1</source>
        <translation>Neue teilnehmende Person: %1</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="156"/>
        <source>Continue %1 (%2 of %3 answered)</source>
        <translation>%1 fortsetzen (%2 von %3 beantwortet)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="165"/>
        <source>Participant:</source>
        <translation>Teilnehmende Person:</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyController.cpp" line="177"/>
        <source>Study results</source>
        <translation>Studienergebnisse</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::StudyResultsView</name>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="41"/>
        <source>Export CSV…</source>
        <translation>CSV exportieren …</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="47"/>
        <source>Method A</source>
        <translation>Methode A</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="47"/>
        <source>A judged real</source>
        <translation>A als echt beurteilt</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="47"/>
        <location filename="../studio/compare/StudyResultsView.cpp" line="52"/>
        <source>Can&apos;t decide</source>
        <translation>Unentschieden</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="48"/>
        <source>B judged real</source>
        <translation>B als echt beurteilt</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="48"/>
        <source>Method B</source>
        <translation>Methode B</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="48"/>
        <source>p (sign test)</source>
        <translation>p (Vorzeichentest)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="49"/>
        <source>p (Holm)</source>
        <translation>p (Holm)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="51"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="51"/>
        <source>Bradley–Terry strength</source>
        <translation>Bradley-Terry-Stärke</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="51"/>
        <source>Judged real</source>
        <translation>Als echt beurteilt</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="52"/>
        <source>Not judged real</source>
        <translation>Nicht als echt beurteilt</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="52"/>
        <source>Judged real (95 % CI)</source>
        <translation>Für echt gehalten (95-%-KI)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="59"/>
        <source>Which one is real? Pairs of methods (as in the paper&apos;s Table 1):</source>
        <translation>Welches ist echt? Methodenpaare (wie in Tabelle 1 des Artikels):</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="61"/>
        <source>Ranking:</source>
        <translation>Rangfolge:</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="78"/>
        <source>The project has no study yet: Study ▸ Set up study…</source>
        <translation>Das Projekt hat noch keine Studie: Studie ▸ Studie einrichten …</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="104"/>
        <source>%1 % (%2–%3 %)</source>
        <translation>%1 % (%2–%3 %)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="110"/>
        <source>Participants: %1, answers: %2 (%3 still open). %4</source>
        <translation>Teilnehmende: %1, Antworten: %2 (%3 noch offen). %4</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="119"/>
        <source>Few answers: a pair has only %1 decided (%2 or more are needed before a ranking says much); read the intervals, not the strengths.</source>
        <translation>Wenige Antworten: ein Paar hat nur %1 entschiedene (erst ab %2 sagt eine Rangfolge etwas aus); lesen Sie die Intervalle, nicht die Stärken.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="143"/>
        <location filename="../studio/compare/StudyResultsView.cpp" line="151"/>
        <source>Export study results</source>
        <translation>Studienergebnisse exportieren</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudyResultsView.cpp" line="145"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::StudySetupDialog</name>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="25"/>
        <source>Real (the recorded video)</source>
        <translation>Echt (das aufgenommene Video)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="34"/>
        <source>Train each model without these utterances (the paper&apos;s design)</source>
        <translation>Jedes Modell ohne diese Äußerungen trainieren (das Design des Artikels)</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="37"/>
        <source>Set up blind study</source>
        <translation>Blindstudie einrichten</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="48"/>
        <source>Each model is retrained, with the settings its file records, on the project&apos;s other sequences: viewers judge speech the models have not seen.</source>
        <translation>Jedes Modell wird mit den in seiner Datei festgehaltenen Einstellungen auf den übrigen Sequenzen des Projekts neu trainiert: Die Zuschauer beurteilen Sprache, die die Modelle nicht gesehen haben.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="58"/>
        <source>Methods to compare:</source>
        <translation>Zu vergleichende Methoden:</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="59"/>
        <source>Utterances:</source>
        <translation>Äußerungen:</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="60"/>
        <source>Each pair shown (× 2, sides swapped):</source>
        <translation>Jedes Paar gezeigt (× 2, Seiten vertauscht):</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="61"/>
        <source>Random seed:</source>
        <translation>Zufallsstartwert:</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="87"/>
        <source>Choose at least two methods (train models in the Models panel).</source>
        <translation>Mindestens zwei Methoden wählen (Modelle im Modelle-Bereich trainieren).</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="92"/>
        <source>No sequence has both features and phones yet.</source>
        <translation>Noch keine Sequenz hat sowohl Merkmale als auch Phone.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="97"/>
        <source>Holding out every utterance leaves nothing to train the models on.</source>
        <translation>Wenn alle Äußerungen zurückgehalten werden, bleibt nichts, um die Modelle zu trainieren.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="123"/>
        <source>%1 pairs of methods, each shown %2 times with sides swapped: %3 trials per participant, in a fresh random order for each participant.</source>
        <translation>%1 Methodenpaare, jedes %2-mal mit vertauschten Seiten gezeigt: %3 Durchgänge pro Person, für jede Person in neuer zufälliger Reihenfolge.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="130"/>
        <source>The models are retrained without these utterances before the first trial.</source>
        <translation>Die Modelle werden vor dem ersten Durchgang ohne diese Äußerungen neu trainiert.</translation>
    </message>
    <message>
        <location filename="../studio/compare/StudySetupDialog.cpp" line="131"/>
        <source>Warning: the models were trained on these utterances, so viewers judge speech the models have seen; the paper&apos;s study held its 80 sequences out.</source>
        <translation>Achtung: Die Modelle wurden auf diesen Äußerungen trainiert, die Zuschauer beurteilen also Sprache, die die Modelle gesehen haben; die Studie des Artikels hielt ihre 80 Sequenzen zurück.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TaskListModel</name>
    <message>
        <location filename="../studio/tasks/TaskListModel.cpp" line="74"/>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskListModel.cpp" line="75"/>
        <source>Finished</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskListModel.cpp" line="76"/>
        <source>Canceled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskListModel.cpp" line="77"/>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TaskListPopup</name>
    <message>
        <location filename="../studio/tasks/TaskListPopup.cpp" line="24"/>
        <source>Background tasks</source>
        <translation>Hintergrundaufgaben</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskListPopup.cpp" line="28"/>
        <source>Clear finished</source>
        <translation>Beendete entfernen</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskListPopup.cpp" line="76"/>
        <source>No background tasks.</source>
        <translation>Keine Hintergrundaufgaben.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TaskRowWidget</name>
    <message>
        <location filename="../studio/tasks/TaskRowWidget.cpp" line="32"/>
        <source>Cancel this task</source>
        <translation>Diese Aufgabe abbrechen</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskRowWidget.cpp" line="58"/>
        <source>Canceling…</source>
        <translation>Wird abgebrochen …</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskRowWidget.cpp" line="62"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TaskStatusWidget</name>
    <message>
        <location filename="../studio/tasks/TaskStatusWidget.cpp" line="32"/>
        <source>Cancel this task</source>
        <translation>Diese Aufgabe abbrechen</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskStatusWidget.cpp" line="36"/>
        <source>Show all background tasks</source>
        <translation>Alle Hintergrundaufgaben anzeigen</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/tasks/TaskStatusWidget.cpp" line="71"/>
        <source> (+%n more)</source>
        <translation>
            <numerusform> (+%n weitere)</numerusform>
            <numerusform> (+%n weitere)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskStatusWidget.cpp" line="75"/>
        <source>All tasks done</source>
        <translation>Alle Aufgaben erledigt</translation>
    </message>
    <message>
        <location filename="../studio/tasks/TaskStatusWidget.cpp" line="75"/>
        <source>No tasks</source>
        <translation>Keine Aufgaben</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TimelinePanel</name>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="189"/>
        <source>Zoom out (wheel down)</source>
        <translation>Verkleinern (Mausrad nach unten)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="190"/>
        <source>Zoom in (wheel up)</source>
        <translation>Vergrößern (Mausrad nach oben)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="191"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="191"/>
        <source>Show the whole sequence</source>
        <translation>Die ganze Sequenz zeigen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="88"/>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="462"/>
        <source>Align</source>
        <translation>Ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="88"/>
        <source>Align this sequence&apos;s transcript to its audio (words and phones)</source>
        <translation>Das Transkript dieser Sequenz am Ton ausrichten (Wörter und Phone)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="89"/>
        <source>Align All</source>
        <translation>Alle ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="89"/>
        <source>Align every sequence that has a transcript</source>
        <translation>Jede Sequenz mit Transkript ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="90"/>
        <source>Re-align Selection</source>
        <translation>Auswahl neu ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="91"/>
        <source>Align the selected stretch again, keeping the words whose timing you edited</source>
        <translation>Den ausgewählten Abschnitt neu ausrichten; Wörter mit bearbeitetem Timing bleiben</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="95"/>
        <source>Adapt to Speaker</source>
        <translation>An Sprecher anpassen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="106"/>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="527"/>
        <source>Built-in Model (GRID Speaker)</source>
        <translation>Eingebautes Modell (GRID-Sprecher)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="107"/>
        <source>Align with the model shipped with the studio, trained on one GRID speaker</source>
        <translation>Mit dem mitgelieferten Modell ausrichten, trainiert auf einem GRID-Sprecher</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="108"/>
        <source>Generic US English (CMU Sphinx)</source>
        <translation>Allgemeines US-Englisch (CMU Sphinx)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="109"/>
        <source>Align with CMU Sphinx&apos;s US-English model trained on many speakers (Debian package pocketsphinx-en-us)</source>
        <translation>Mit dem US-englischen Modell von CMU Sphinx ausrichten, trainiert auf vielen Sprechern (Debian-Paket pocketsphinx-en-us)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="126"/>
        <source>Split at Cursor</source>
        <translation>Am Cursor teilen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="126"/>
        <source>Split the interval under the cursor</source>
        <translation>Das Intervall unter dem Cursor teilen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="127"/>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="681"/>
        <source>Merge with Next</source>
        <translation>Mit nächstem verbinden</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="127"/>
        <source>Join the selected interval with the next one</source>
        <translation>Das ausgewählte Intervall mit dem nächsten verbinden</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="129"/>
        <source>Relabel…</source>
        <translation>Umbenennen…</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="129"/>
        <source>Change the label of the selected interval</source>
        <translation>Die Beschriftung des ausgewählten Intervalls ändern</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="131"/>
        <source>Insert Silence</source>
        <translation>Stille einfügen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="131"/>
        <source>Make the selection a silence</source>
        <translation>Die Auswahl zur Stille machen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="132"/>
        <source>Insert Breath</source>
        <translation>Atmer einfügen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="132"/>
        <source>Make the selection a breath</source>
        <translation>Die Auswahl zum Atmer machen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="133"/>
        <source>Play Selection</source>
        <translation>Auswahl abspielen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="133"/>
        <source>Play the selected stretch (Space in the timeline)</source>
        <translation>Den ausgewählten Abschnitt abspielen (Leertaste in der Zeitleiste)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="134"/>
        <source>Play Word</source>
        <translation>Wort abspielen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="134"/>
        <source>Play the word under the cursor</source>
        <translation>Das Wort unter dem Cursor abspielen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="135"/>
        <source>Play All</source>
        <translation>Alles abspielen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="135"/>
        <source>Play the whole sequence</source>
        <translation>Die ganze Sequenz abspielen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="136"/>
        <source>Pronunciations…</source>
        <translation>Aussprachen…</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="137"/>
        <source>The project&apos;s pronunciations, and the words espeak-ng guessed</source>
        <translation>Die Aussprachen des Projekts und die von espeak-ng geschätzten Wörter</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="178"/>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="179"/>
        <source>The acoustic model the aligner uses</source>
        <translation>Das akustische Modell, das die Ausrichtung verwendet</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="143"/>
        <source>Show Spectrogram</source>
        <translation>Spektrogramm anzeigen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="144"/>
        <source>Show the spectrogram under the waveform in the timeline</source>
        <translation>Das Spektrogramm unter der Wellenform in der Zeitleiste anzeigen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="304"/>
        <source>No audio: %1</source>
        <translation>Kein Ton: %1</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="323"/>
        <source>Alignment of the speech in the Preview: %1 (read-only; Back to Sequence there to edit)</source>
        <translation>Alignierung der Sprache in der Vorschau: %1 (schreibgeschützt; dort „Zurück zur Sequenz“ zum Bearbeiten)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="337"/>
        <source>No audio</source>
        <translation>Kein Ton</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="426"/>
        <source>Align %1</source>
        <translation>%1 ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="439"/>
        <source>No sequence has a transcript to align.</source>
        <translation>Keine Sequenz hat ein Transkript zum Ausrichten.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="463"/>
        <source>The transcript of %1 changed since its boundaries were edited. Aligning it again replaces the edited boundaries. Align anyway?</source>
        <translation>Das Transkript von %1 wurde geändert, nachdem seine Grenzen bearbeitet wurden. Erneutes Alignieren ersetzt die bearbeiteten Grenzen. Trotzdem alignieren?</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="474"/>
        <source>Every word of %1 is user-edited: nothing to align there.</source>
        <translation>Jedes Wort von %1 ist von Hand bearbeitet: Dort gibt es nichts zu alignieren.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="495"/>
        <source>Nothing to re-align: the selection holds no words, or only words you edited.</source>
        <translation>Nichts neu auszurichten: Die Auswahl enthält keine Wörter oder nur von Ihnen bearbeitete.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="498"/>
        <source>Re-align %1</source>
        <translation>%1 neu ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="444"/>
        <source>Align all sequences</source>
        <translation>Alle Sequenzen ausrichten</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="96"/>
        <source>Adapt the aligner to each recording&apos;s voice before aligning it (slower; better for voices unlike the model&apos;s training speakers)</source>
        <translation>Den Aligner vor dem Ausrichten an die Stimme jeder Aufnahme anpassen (langsamer; besser für Stimmen, die den Trainingssprechern des Modells unähnlich sind)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="262"/>
        <source>The timeline aligns with Generic US English, adapted to each recording&apos;s speaker (Model menu): the built-in model knows only GRID&apos;s speaker s1.</source>
        <translation>Die Zeitleiste aligniert mit Allgemeines US-Englisch, an den Sprecher jeder Aufnahme angepasst (Menü Modell): Das eingebaute Modell kennt nur GRIDs Sprecher s1.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="264"/>
        <source>The timeline aligns with the built-in model of GRID&apos;s speaker s1. For another speaker, choose Model ▸ Generic US English and Adapt to Speaker.</source>
        <translation>Die Zeitleiste richtet mit dem eingebauten Modell des GRID-Sprechers s1 aus. Für einen anderen Sprecher wählen Sie Modell ▸ Allgemeines US-Englisch und An Sprecher anpassen.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="528"/>
        <source>The Project&apos;s Aligner (%1)</source>
        <translation>Aligner des Projekts (%1)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="553"/>
        <source>The alignment failed.</source>
        <translation>Die Ausrichtung ist fehlgeschlagen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/timeline/TimelinePanel.cpp" line="578"/>
        <source>espeak-ng guessed the pronunciation of %n word(s): check them in Pronunciations…</source>
        <translation>
            <numerusform>espeak-ng hat die Aussprache von %n Wort/Wörtern geschätzt: prüfen Sie sie unter Aussprachen…</numerusform>
            <numerusform>espeak-ng hat die Aussprache von %n Wort/Wörtern geschätzt: prüfen Sie sie unter Aussprachen…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="600"/>
        <source>%1: the alignment came out as it was; nothing changed.</source>
        <translation>%1: Die Alignierung ist unverändert geblieben.</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="607"/>
        <source>No transcript fits its sound by this aligner: its model probably does not know this speaker. Choose Model ▸ Generic US English and Adapt to Speaker, or train the project&apos;s own aligner.</source>
        <translation>Nach diesem Aligner passt kein Transkript zu seinem Ton: Sein Modell kennt diesen Sprecher vermutlich nicht. Wählen Sie Modell ▸ Allgemeines US-Englisch und An Sprecher anpassen, oder trainieren Sie den eigenen Aligner des Projekts.</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/timeline/TimelinePanel.cpp" line="612"/>
        <source>%n transcript(s) do not fit the sound: %1. Check that they are the clips&apos; words (marked in the sequence list).</source>
        <translation>
            <numerusform>%n Transkript passt nicht zum Ton: %1. Prüfen Sie, ob es die Wörter des Clips sind (in der Sequenzliste markiert).</numerusform>
            <numerusform>%n Transkripte passen nicht zum Ton: %1. Prüfen Sie, ob es die Wörter der Clips sind (in der Sequenzliste markiert).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/timeline/TimelinePanel.cpp" line="618"/>
        <source>%n sequence(s) could not be aligned; the others were.</source>
        <translation>
            <numerusform>%n Sequenz konnte nicht ausgerichtet werden; die anderen wurden ausgerichtet.</numerusform>
            <numerusform>%n Sequenzen konnten nicht ausgerichtet werden; die anderen wurden ausgerichtet.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="657"/>
        <source>Move word boundary</source>
        <translation>Wortgrenze verschieben</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="657"/>
        <source>Move phone boundary</source>
        <translation>Phongrenze verschieben</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="665"/>
        <source>Split interval</source>
        <translation>Intervall teilen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="682"/>
        <source>These phones belong to two words, “%1” and “%2”. Merge the words as well?</source>
        <translation>Diese Phone gehören zu zwei Wörtern, „%1“ und „%2“. Die Wörter ebenfalls verbinden?</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="685"/>
        <source>Merge Phones and Words</source>
        <translation>Phone und Wörter verbinden</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="691"/>
        <source>Merge intervals</source>
        <translation>Intervalle verbinden</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="691"/>
        <source>Merge phones and words</source>
        <translation>Phone und Wörter verbinden</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="723"/>
        <source>Insert breath</source>
        <translation>Atmer einfügen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="723"/>
        <source>Insert silence</source>
        <translation>Stille einfügen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="744"/>
        <source>Relabel as %1</source>
        <translation>Umbenennen in %1</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TrajectoryView</name>
    <message>
        <location filename="../studio/plots/TrajectoryView.cpp" line="192"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../studio/plots/TrajectoryView.cpp" line="193"/>
        <source>parameter value</source>
        <translation>Parameterwert</translation>
    </message>
    <message>
        <location filename="../studio/plots/TrajectoryView.cpp" line="246"/>
        <source>phonemes</source>
        <translation>Phoneme</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TranscriptProposer</name>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="29"/>
        <source>&amp;Propose Transcript</source>
        <translation>Transkript &amp;vorschlagen</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="42"/>
        <source>&amp;Accept Proposed Transcript</source>
        <translation>Vorgeschlagenes Transkript &amp;übernehmen</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="39"/>
        <source>Propose a transcript of this sequence by speech recognition (CMU Sphinx&apos;s US-English models), marked as not checked until you edit or accept it</source>
        <translation>Ein Transkript dieser Sequenz per Spracherkennung vorschlagen (die US-englischen Modelle von CMU Sphinx), als nicht geprüft markiert, bis Sie es bearbeiten oder übernehmen</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="41"/>
        <source>Needs CMU Sphinx&apos;s US-English model (Debian package pocketsphinx-en-us)</source>
        <translation>Benötigt das US-englische Modell von CMU Sphinx (Debian-Paket pocketsphinx-en-us)</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="50"/>
        <source>Take the proposed transcript of this sequence as checked, as it is</source>
        <translation>Das vorgeschlagene Transkript dieser Sequenz unverändert als geprüft übernehmen</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="92"/>
        <source>Propose Transcript</source>
        <translation>Transkript vorschlagen</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="93"/>
        <source>%1 has a transcript. Proposing one replaces it with the words speech recognition hears. Propose anyway?</source>
        <translation>%1 hat ein Transkript. Ein Vorschlag ersetzt es durch die Wörter, die die Spracherkennung hört. Trotzdem vorschlagen?</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="101"/>
        <source>Propose transcript of %1</source>
        <translation>Transkript von %1 vorschlagen</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="121"/>
        <source>No transcript could be proposed.</source>
        <translation>Es konnte kein Transkript vorgeschlagen werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="142"/>
        <source>The transcript of %1 changed while its speech was recognised: the proposal was not applied.</source>
        <translation>Das Transkript von %1 wurde geändert, während seine Sprache erkannt wurde: Der Vorschlag wurde nicht übernommen.</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="149"/>
        <source>Speech recognition proposes the transcript %1 has: nothing changed.</source>
        <translation>Die Spracherkennung schlägt das Transkript vor, das %1 schon hat: Nichts wurde geändert.</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="156"/>
        <source>Transcript of %1 proposed: check it, then edit or accept it.</source>
        <translation>Transkript von %1 vorgeschlagen: Prüfen Sie es, dann bearbeiten oder übernehmen Sie es.</translation>
    </message>
    <message>
        <location filename="../studio/app/TranscriptProposer.cpp" line="158"/>
        <source>Transcript of %1 proposed: check it, the most doubtful words first: %2.</source>
        <translation>Transkript von %1 vorgeschlagen: Prüfen Sie es, die unsichersten Wörter zuerst: %2.</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::TransportBar</name>
    <message>
        <location filename="../studio/app/TransportBar.cpp" line="29"/>
        <source>Frame</source>
        <translation>Bild</translation>
    </message>
    <message>
        <location filename="../studio/app/TransportBar.cpp" line="75"/>
        <source>%1 s / %2 s</source>
        <translation>%1 s / %2 s</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::UserGuide</name>
    <message>
        <location filename="../studio/app/UserGuide.cpp" line="19"/>
        <source>User Guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../studio/app/UserGuide.cpp" line="24"/>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <location filename="../studio/app/UserGuide.cpp" line="25"/>
        <source>Contents</source>
        <translation>Inhalt</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::WaveformView</name>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="451"/>
        <source>spectrogram</source>
        <translation>Spektrogramm</translation>
    </message>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="475"/>
        <source>No phones yet: align the sequence (Align)</source>
        <translation>Noch keine Phone: Sequenz ausrichten (Ausrichten)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="475"/>
        <source>No words</source>
        <translation>Keine Wörter</translation>
    </message>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="476"/>
        <location filename="../studio/timeline/WaveformView.cpp" line="517"/>
        <source>phones</source>
        <translation>Phone</translation>
    </message>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="476"/>
        <location filename="../studio/timeline/WaveformView.cpp" line="517"/>
        <source>words</source>
        <translation>Wörter</translation>
    </message>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="524"/>
        <source>frame labels</source>
        <translation>Bildlabels</translation>
    </message>
    <message>
        <location filename="../studio/timeline/WaveformView.cpp" line="546"/>
        <source>frames</source>
        <translation>Bilder</translation>
    </message>
</context>
</TS>
