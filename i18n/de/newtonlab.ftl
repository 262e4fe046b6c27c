# Die Texte von NewtonLab auf Deutsch (Vorlage: i18n/en/newtonlab.ftl).

## Menus
menu-file = Datei
menu-file-hint = Neu, öffnen, speichern, teilen
menu-new = Neu
menu-new-hint = Eine leere Szene
menu-open = Öffnen…
menu-open-hint = Eine Szenendatei öffnen
menu-save = Speichern
menu-save-hint = Die Szene speichern
menu-save-canvas = Zeichenfläche als PNG speichern…
menu-save-canvas-hint = Ein Bild der Zeichenfläche, wie sie zu sehen ist
menu-save-as = Speichern unter…
menu-save-as-hint = Die Szene unter einem anderen Namen speichern
menu-copy-link = Link zu dieser Szene kopieren
menu-copy-link-hint = Ein Link, der diese Szene öffnet: in der Adressleiste und in der Zwischenablage
menu-link-copied = Ein Link zu dieser Szene steht in der Adressleiste und in der Zwischenablage.
menu-edit = Bearbeiten
menu-edit-hint = Rückgängig, wiederholen, löschen
menu-undo = Rückgängig
menu-undo-what = Rückgängig: { $what }
menu-undo-hint = Die letzte Änderung rückgängig machen
menu-redo = Wiederholen
menu-redo-what = Wiederholen: { $what }
menu-redo-hint = Das Rückgängig gemachte wiederholen
menu-delete = Löschen
menu-delete-hint = Das ausgewählte Objekt entfernen
menu-examples = Beispiele
menu-examples-hint = Eine eingebaute Szene öffnen (die Versuche des Berichts und mehr)
menu-view = Ansicht
menu-view-hint = Ausschnitt, Leisten, Projektormodus, Sprache
menu-fit = Einpassen
menu-fit-hint = Die Szene und die letzten Bahnen ins Bild holen
menu-inspector = Inspektor
menu-inspector-hint = Den Inspektor zeigen oder verbergen
menu-graphs = Diagramme
menu-graphs-hint = Die Diagramme und Anzeigen zeigen oder verbergen
menu-projector = Projektormodus
menu-projector-hint = Nur die Zeichenfläche, mit großer Schrift, für eine Klasse
menu-follow = Folgen
menu-follow-hint = Ein Teilchen oder alle beim Abspielen im Bild halten
menu-language = Sprache
menu-language-hint = Die Sprache der App; sie wechselt sofort
menu-text-size = Textgröße
menu-text-size-hint = Größere Schrift und Bedienelemente; bleibt für das nächste Mal
menu-high-contrast = Hoher Kontrast
menu-high-contrast-hint = Schwarz auf Weiß mit kräftigen Umrissen; bleibt für das nächste Mal
menu-measure = Messen
menu-measure-hint = Maßband, Feldsonde, Feldansicht
menu-no-field = Keine Feldansicht
menu-electric-field = Elektrisches Feld
menu-gravitational-field = Gravitationsfeld
menu-field-hint = Pfeile des Felds der Teilchen über der Zeichenfläche, dunkler wo stärker
menu-stopwatch = Stoppuhr
menu-stopwatch-hint = Simulierte Zeit zwischen zwei Ereignissen: von Hand, ein Stoß, ein Teilchen, das das Maßband kreuzt
menu-clear-measurements = Messungen entfernen
menu-clear-measurements-hint = Maßband, Sonde und Winkelmesser wegnehmen
menu-help = Hilfe
menu-keys = Tasten
menu-keys-hint = Alle Tastenkürzel und wie man die Zeichenfläche mit der Tastatur bedient

## Tool bar
toolbar-play = Start
toolbar-pause = Pause
toolbar-play-hint = Die Simulation starten oder anhalten (Leertaste)
toolbar-step = Schritt
toolbar-step-hint = Um einen Zeitschritt weiter (.)
toolbar-reset = Zurücksetzen
toolbar-reset-hint = Zurück zur zuletzt bearbeiteten Szene (R)
toolbar-time-scale-hint = Zeitmaßstab: simulierte Sekunden pro echter Sekunde (0,01× bis 100×)
toolbar-integrator-hint = Wie die Bewegung in der Zeit integriert wird
toolbar-time-step-hint = Zeitschritt in Sekunden (dopri5: der größte Schritt)
toolbar-fit-hint = Die Szene und die letzten Bahnen ins Bild holen (F)
toolbar-velocity = Geschwindigkeit
toolbar-velocity-hint = Geschwindigkeitspfeile (Spitze: wo das Teilchen in 0,5 s sein wird)
toolbar-acceleration = Beschleunigung
toolbar-acceleration-hint = Beschleunigungspfeile
toolbar-force = Kraft
toolbar-force-hint = Pfeile der Gesamtkraft (die Länge wächst mit dem Logarithmus der Kraft)
toolbar-trails = Spuren
toolbar-trails-hint = Die letzten Bahnen der Teilchen
toolbar-names = Namen
toolbar-names-hint = Namen der Objekte
follow-nothing = nichts
follow-nothing-hint = Eine feste Kamera
follow-all = alle Teilchen
follow-all-hint = Alle Teilchen im Bild halten
follow-particle-hint = Dieses Teilchen in der Mitte halten

## Tools
tool-select = Auswählen
tool-particle = Teilchen
tool-spring = Feder
tool-rod = Stange
tool-string = Faden
tool-ramp = Rampe

## Status line
status-behind = läuft mit { $ratio }× der gewünschten Geschwindigkeit ({ $real }× Echtzeit)
status-real-time = { $real }× Echtzeit
status-paused = angehalten
status-editing = Bearbeiten

## Keys (F1)
keys-title = Tasten
keys-everywhere = Überall (außer beim Tippen in einem Feld)
keys-canvas = Auf der Zeichenfläche
keys-controls = Tab und Umschalt+Tab wechseln zwischen den Bedienelementen; Eingabe oder Leertaste drückt eine Schaltfläche; die Menüs öffnen sich mit einem Klick oder, wenn sie den Fokus haben, mit der Eingabetaste.
key-new = Neue Szene
key-open = Eine Szenendatei öffnen
key-save = Speichern
key-save-as = Speichern unter
key-undo = Rückgängig
key-redo = Wiederholen
key-delete = Das ausgewählte Objekt löschen
key-play-pause = Start oder Pause
key-step = Einen Schritt vor
key-step-back = Einen Schritt zurück im Lauf
key-reset = Zurück zur gebauten Szene
key-fit = Die Ansicht an die Szene anpassen
key-stopwatch = Stoppuhr
key-inspector = Den Inspektor zeigen oder verbergen
key-graphs = Die Diagramme zeigen oder verbergen
key-projector = Projektormodus
key-help = Diese Liste der Tasten
canvas-key-focus = Der Zeichenfläche die Tastatur geben
canvas-key-cycle = Das nächste / vorige Objekt auswählen
canvas-key-move = Das ausgewählte Teilchen oder die Rampe um einen Rasterschritt verschieben
canvas-key-fine = Um ein Zehntel eines Rasterschritts verschieben
canvas-key-enter = Ein Objekt des aktuellen Werkzeugs in der Mitte der Ansicht hinzufügen (eine Feder, Stange oder einen Faden vom ausgewählten Teilchen aus)
canvas-key-escape = Die Tastatur zurückgeben; Tab geht dann zum nächsten Bedienelement
canvas-key-instrument-enter = Mit dem Maßband (M) oder dem Winkelmesser (A): vom ausgewählten Teilchen zu den nächsten legen, oder in die Mitte der Ansicht
canvas-key-instrument-tab = Mit dem Maßband oder dem Winkelmesser: das Ende oder den Punkt wählen, den die Pfeiltasten bewegen
canvas-key-instrument-move = Mit der Sonde, dem Maßband oder dem Winkelmesser: (den gewählten Punkt) um ein Zehntel eines Rasterschritts verschieben; Umschalt ein Hundertstel

## Readouts and graphs
readout-heading = Energie und Impuls
readout-failed = Der Lauf ist gescheitert: die Werte seiner letzten gültigen Probe.
readout-potential = potentiell (J)
readout-potential-field = potentiell: Feld (J)
readout-potential-springs = potentiell: Federn (J)
readout-potential-gravitation = potentiell: Gravitation (J)
readout-potential-electrostatic = potentiell: elektrostatisch (J)
readout-press-play = Start drücken, um Energien und Impuls zu sehen.
readout-kinetic = kinetisch (J)
readout-total = gesamt (J)
readout-total-at-play = gesamt beim Start (J)
readout-damping = durch Dämpfung entzogen (J)
readout-friction = durch Reibung entzogen (J)
readout-impacts = durch Stöße entzogen (J)
readout-ties = Arbeit der Stangen und Fäden (J)
readout-error = numerischer Fehler
readout-momentum = Impuls (kg·m/s)
bar-kinetic = kinetisch
bar-damping = Dämpfung entzog
bar-friction = Reibung entzog
bar-impacts = Stöße entzogen
bar-total-at-play = gesamt beim Start
bars-title = Energiebalken
bars-hint = Jede Energieart im selben Maßstab; die Zahlen stehen in der Tabelle darüber
impacts-title = Stöße ({ $count })
impacts-none = Noch keine Stöße.
graph-add = Diagramm hinzufügen
graph-add-hint = Ein neues Diagramm von Größen über der Zeit
graph-remove = Diagramm entfernen
graph-remove-hint = Dieses Diagramm entfernen (seine Daten bleiben aufgezeichnet)
graph-add-series = Hinzufügen
graph-add-series-hint = Diese Größe zeichnen
graph-x-axis = Als x-Achse verwenden
graph-x-axis-hint = Alles über dieser Größe zeichnen (ein Phasendiagramm)
graph-use-time = Zeit verwenden
graph-use-time-hint = Wieder über der Zeit zeichnen
graph-export-csv = CSV exportieren…
graph-export-csv-hint = Alle aufgezeichneten Proben der Größen dieses Diagramms als CSV-Datei speichern
graph-save-png = PNG speichern…
graph-save-png-hint = Ein Bild dieses Diagramms speichern, wie es zu sehen ist
graph-press-play = Start drücken: das Diagramm füllt sich vom Beginn des Laufs an.

## Announcements for screen readers
announce-impact = Bei { $time } s stieß { $particle } an { $other }.{ $more ->
    [0] {""}
    [one] {" "}Dazu 1 weiterer Stoß seit der letzten Meldung.
   *[other] {" "}Dazu { $more } weitere Stöße seit der letzten Meldung.
}
announce-wall = die Wand
