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
    <name>CommandLine</name>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="10"/>
        <source>LipSync Studio: realistic lip movement from speech.</source>
        <translation>LipSync Studio: realistische Lippenbewegungen aus Sprache.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="13"/>
        <source>Open the project in DIR.</source>
        <translation>Das Projekt im Ordner DIR öffnen.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="16"/>
        <source>User interface language (en, de); default: the system&apos;s.</source>
        <translation>Sprache der Benutzeroberfläche (en, de); Vorgabe: die des Systems.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="19"/>
        <source>Render the main window into FILE (PNG) once the project has loaded, then exit.</source>
        <translation>Das Hauptfenster nach dem Laden des Projekts in DATEI (PNG) speichern und beenden.</translation>
    </message>
    <message>
        <location filename="../studio/app/CommandLine.cpp" line="22"/>
        <source>Project folder (or its project.json).</source>
        <translation>Projektordner (oder dessen project.json).</translation>
    </message>
</context>
<context>
    <name>ErrorReporter</name>
    <message>
        <location filename="../studio/app/ErrorReporter.cpp" line="21"/>
        <source>File: %1</source>
        <translation>Datei: %1</translation>
    </message>
    <message>
        <location filename="../studio/app/ErrorReporter.cpp" line="24"/>
        <source>Reason: %1</source>
        <translation>Grund: %1</translation>
    </message>
    <message>
        <location filename="../studio/app/ErrorReporter.cpp" line="30"/>
        <source>LipSync Studio</source>
        <translation>LipSync Studio</translation>
    </message>
</context>
<context>
    <name>SequenceLoader</name>
    <message>
        <location filename="../studio/app/SequenceLoader.cpp" line="45"/>
        <source>Decoding audio</source>
        <translation>Audio wird dekodiert</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceLoader.cpp" line="59"/>
        <source>Reading video frames</source>
        <translation>Videobilder werden gelesen</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceLoader.cpp" line="84"/>
        <source>Loading %1</source>
        <translation>%1 wird geladen</translation>
    </message>
</context>
<context>
    <name>SetTranscriptCommand</name>
    <message>
        <location filename="../studio/app/SetTranscriptCommand.cpp" line="12"/>
        <source>Edit transcript of %1</source>
        <translation>Transkript von %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>StudioActions</name>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="32"/>
        <source>&amp;Open Project…</source>
        <translation>Projekt &amp;öffnen …</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="33"/>
        <source>Open &amp;Demo Project</source>
        <translation>&amp;Demoprojekt öffnen</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="34"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="35"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="36"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="38"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="41"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="47"/>
        <source>Previous Frame</source>
        <translation>Vorheriges Bild</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="48"/>
        <source>Next Frame</source>
        <translation>Nächstes Bild</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="49"/>
        <source>First Frame</source>
        <translation>Erstes Bild</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="50"/>
        <source>Last Frame</source>
        <translation>Letztes Bild</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="51"/>
        <source>Play/Pause</source>
        <translation>Wiedergabe/Pause</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="52"/>
        <source>Previous Sequence</source>
        <translation>Vorherige Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="53"/>
        <source>Next Sequence</source>
        <translation>Nächste Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="54"/>
        <source>Fit Frame to View</source>
        <translation>Bild einpassen</translation>
    </message>
    <message>
        <location filename="../studio/app/StudioActions.cpp" line="55"/>
        <source>&amp;About LipSync Studio</source>
        <translation>&amp;Über LipSync Studio</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::MainWindow</name>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="60"/>
        <source>Annotate</source>
        <translation>Annotieren</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="61"/>
        <source>Preview &amp;&amp; Compare</source>
        <translation>Vorschau &amp;&amp; Vergleich</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="85"/>
        <location filename="../studio/app/MainWindow.cpp" line="86"/>
        <source>No project open</source>
        <translation>Kein Projekt geöffnet</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="133"/>
        <source>Sequences</source>
        <translation>Sequenzen</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="137"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="142"/>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="145"/>
        <source>Models</source>
        <translation>Modelle</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="157"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="159"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="168"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="172"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="182"/>
        <source>&amp;Panels</source>
        <translation>&amp;Bereiche</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="186"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="189"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="236"/>
        <source>Select a sequence</source>
        <translation>Wählen Sie eine Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="281"/>
        <source>Loading %1…</source>
        <translation>%1 wird geladen …</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="289"/>
        <source>The media of this sequence could not be read.</source>
        <translation>Die Mediendatei dieser Sequenz konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="323"/>
        <source>No audio: %1</source>
        <translation>Kein Ton: %1</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="325"/>
        <source>The video has no frames</source>
        <translation>Das Video enthält keine Bilder</translation>
    </message>
    <message numerus="yes">
        <location filename="../studio/app/MainWindow.cpp" line="329"/>
        <source>%1: %n frames at %2 fps</source>
        <translation>
            <numerusform>%1: %n Bild mit %2 fps</numerusform>
            <numerusform>%1: %n Bilder mit %2 fps</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="339"/>
        <source>Audio energy of %1</source>
        <translation>Audioenergie von %1</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="340"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="340"/>
        <source>RMS per video frame</source>
        <translation>RMS je Videobild</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="346"/>
        <source>RMS</source>
        <translation>RMS</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="363"/>
        <source>%1 — frame %2 of %3</source>
        <translation>%1 – Bild %2 von %3</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="379"/>
        <location filename="../studio/app/MainWindow.cpp" line="387"/>
        <source>LipSync Studio</source>
        <translation>LipSync Studio</translation>
    </message>
    <message>
        <location filename="../studio/app/MainWindow.cpp" line="386"/>
        <source> (bundled demo, read-only)</source>
        <translation> (mitgeliefertes Demo, schreibgeschützt)</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ModelsPanel</name>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="17"/>
        <source>Appearance model</source>
        <translation>Erscheinungsmodell</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="18"/>
        <source>Phoneme aligner</source>
        <translation>Phonem-Aligner</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="19"/>
        <source>DPDS</source>
        <translation>DPDS</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="20"/>
        <source>SLDS</source>
        <translation>SLDS</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="21"/>
        <source>Voice Puppetry</source>
        <translation>Voice Puppetry</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="22"/>
        <source>Phoneme-mean HMM</source>
        <translation>Phonem-Mittelwert-HMM</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="29"/>
        <source>Build AAM…</source>
        <translation>AAM erstellen …</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="30"/>
        <source>Train…</source>
        <translation>Trainieren …</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="34"/>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="34"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="34"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="45"/>
        <source>Building an Active Appearance Model comes with the faces feature (landmark editor, AAM building and fitting).</source>
        <translation>Das Erstellen eines Active Appearance Model kommt mit der Gesichtsfunktion (Landmarken-Editor, AAM-Erstellung und -Anpassung).</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="48"/>
        <source>Training dynamic models comes with the dynamics feature (DPDS, SLDS, Voice Puppetry, phoneme means).</source>
        <translation>Das Trainieren dynamischer Modelle kommt mit der Dynamikfunktion (DPDS, SLDS, Voice Puppetry, Phonem-Mittelwerte).</translation>
    </message>
    <message>
        <location filename="../studio/build/ModelsPanel.cpp" line="64"/>
        <source>No models yet</source>
        <translation>Noch keine Modelle</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::PreviewPanel</name>
    <message>
        <location filename="../studio/preview/PreviewPanel.cpp" line="21"/>
        <source>Recorded video</source>
        <translation>Aufgenommenes Video</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ProjectFiles</name>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="29"/>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="30"/>
        <source>LipSync projects (project.json)</source>
        <translation>LipSync-Projekte (project.json)</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="44"/>
        <source>The project could not be opened.</source>
        <translation>Das Projekt konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="56"/>
        <source>The bundled demo project was not found.</source>
        <translation>Das mitgelieferte Demoprojekt wurde nicht gefunden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="57"/>
        <source>Looked in $LIPSYNC_DEMO_DIR, &lt;prefix&gt;/share/lipsync/demo and the source tree.</source>
        <translation>Gesucht in $LIPSYNC_DEMO_DIR, &lt;prefix&gt;/share/lipsync/demo und im Quellbaum.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="63"/>
        <source>The demo project could not be opened.</source>
        <translation>Das Demoprojekt konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="85"/>
        <source>Save Project As (a folder)</source>
        <translation>Projekt speichern unter (ein Ordner)</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="90"/>
        <location filename="../studio/app/ProjectFiles.cpp" line="108"/>
        <source>The project could not be saved.</source>
        <translation>Das Projekt konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="91"/>
        <source>a file of that name exists; a project needs a folder</source>
        <translation>es gibt eine Datei dieses Namens; ein Projekt braucht einen Ordner</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="96"/>
        <source>Replace Project</source>
        <translation>Projekt ersetzen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="97"/>
        <source>%1 already holds a project. Replace it?</source>
        <translation>%1 enthält bereits ein Projekt. Ersetzen?</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="121"/>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../studio/app/ProjectFiles.cpp" line="121"/>
        <source>The project has unsaved changes. Save them?</source>
        <translation>Das Projekt hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::RecentProjects</name>
    <message>
        <location filename="../studio/app/RecentProjects.cpp" line="54"/>
        <source>No recent projects</source>
        <translation>Keine zuletzt geöffneten Projekte</translation>
    </message>
    <message>
        <location filename="../studio/app/RecentProjects.cpp" line="58"/>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::ScreenshotRunner</name>
    <message>
        <location filename="../studio/app/ScreenshotRunner.cpp" line="33"/>
        <source>lipsync-studio: timed out waiting for the project to load</source>
        <translation>lipsync-studio: Zeitüberschreitung beim Laden des Projekts</translation>
    </message>
    <message>
        <location filename="../studio/app/ScreenshotRunner.cpp" line="57"/>
        <source>lipsync-studio: cannot write %1</source>
        <translation>lipsync-studio: %1 kann nicht geschrieben werden</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::SequenceDetailsView</name>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="26"/>
        <source>Media:</source>
        <translation>Medien:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="27"/>
        <source>Video:</source>
        <translation>Video:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="28"/>
        <source>Audio:</source>
        <translation>Audio:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="29"/>
        <source>Words:</source>
        <translation>Wörter:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="30"/>
        <source>Landmarks:</source>
        <translation>Landmarken:</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="40"/>
        <source>No sequence</source>
        <translation>Keine Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="53"/>
        <source>%1 frames at %2 fps, %3 × %4</source>
        <translation>%1 Bilder mit %2 fps, %3 × %4</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="59"/>
        <source>%1 s, decoded at %2 Hz mono</source>
        <translation>%1 s, dekodiert mit %2 Hz mono</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="63"/>
        <source>none (%1)</source>
        <translation>keiner (%1)</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="67"/>
        <source>%1 timed words</source>
        <translation>%1 Wörter mit Zeitangaben</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceDetailsView.cpp" line="68"/>
        <source>%1 of %2 frames</source>
        <translation>%1 von %2 Bildern</translation>
    </message>
</context>
<context>
    <name>lipsync::studio::SequenceListModel</name>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="42"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="48"/>
        <source>Double-click to edit the transcript</source>
        <translation>Doppelklicken, um das Transkript zu bearbeiten</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="49"/>
        <source>%1 — %2 frames at %3 fps</source>
        <translation>%1 – %2 Bilder mit %3 fps</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="77"/>
        <source>Sequence</source>
        <translation>Sequenz</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="78"/>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="79"/>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <location filename="../studio/app/SequenceListModel.cpp" line="80"/>
        <source>Transcript</source>
        <translation>Transkript</translation>
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
        <location filename="../studio/timeline/TimelinePanel.cpp" line="38"/>
        <source>Zoom out (wheel down)</source>
        <translation>Verkleinern (Mausrad nach unten)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="39"/>
        <source>Zoom in (wheel up)</source>
        <translation>Vergrößern (Mausrad nach oben)</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="40"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location filename="../studio/timeline/TimelinePanel.cpp" line="40"/>
        <source>Show the whole sequence</source>
        <translation>Die ganze Sequenz zeigen</translation>
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
        <location filename="../studio/app/TransportBar.cpp" line="73"/>
        <source>%1 s / %2 s</source>
        <translation>%1 s / %2 s</translation>
    </message>
</context>
</TS>
