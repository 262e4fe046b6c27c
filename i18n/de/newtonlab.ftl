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
menu-save-canvas-hint = Ein Bild der Zeichenfläche, wie sie zu sehen ist, zum Drucken in doppelter Bildschirmauflösung (im Browser wie auf dem Bildschirm)
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
menu-cut = Ausschneiden
menu-cut-hint = Das ausgewählte Objekt kopieren und dann entfernen
menu-copy = Kopieren
menu-copy-hint = Das ausgewählte Objekt (eine Feder, Stange oder einen Faden mit den verbundenen Teilchen) als Szenen-Text kopieren
menu-paste = Einfügen
menu-paste-hint = Das Kopierte neben seinem Ort einfügen, umbenannt, wo Namen vergeben sind (Strg+V fügt Szenen-Text auch aus anderen Programmen ein)
menu-duplicate = Duplizieren
menu-duplicate-hint = Das ausgewählte Objekt kopieren und daneben einfügen
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
menu-getting-started = Erste Schritte
menu-getting-started-hint = Drei kurze Aufgaben: setzen und laufen lassen, messen, Diagramme
start-title = Erste Schritte
start-intro = Drei kurze Aufgaben, je eine Minute, um sich zurechtzufinden. Hilfe › Erste Schritte öffnet diese Seite wieder; F1 zeigt alle Tasten.
start-place = Setzen und laufen lassen
start-place-1 = Datei › Neu: eine leere Szene mit Schwerkraft.
start-place-2 = 2 drücken (Teilchen) und auf die Zeichenfläche klicken: eine Kugel von 1 kg.
start-place-3 = Im Inspektor links eine Geschwindigkeit x von 3 eingeben (Einheiten gehen auch: 30 km/h).
start-place-4 = Leertaste startet, noch einmal hält an; R setzt auf die Szene zurück, wie Sie sie gebaut haben.
start-measure = Messen
start-measure-1 = Beispiele › Pendulum on a rod, released at 60°; Leertaste, und nach ein, zwei Schwingungen wieder Leertaste.
start-measure-2 = Unter dem Diagramm Extrema und Nullstellen ankreuzen: es zeigt die Periode, 3,044625 s, wie die Theorie sie gibt.
start-measure-3 = Umkehr » in der Zeitleiste zeigt den Pendelkörper genau an seinem nächsten Umkehrpunkt.
start-graph = Diagramme
start-graph-1 = Diagramm hinzufügen, ein Teilchen und eine Größe wählen, dann Hinzufügen.
start-graph-2 = vx wählen und Als x-Achse verwenden: ein Phasendiagramm. Auch eine später hinzugefügte Reihe hat den ganzen Lauf.
start-graph-3 = CSV exportieren… speichert jede Probe für eine Tabellenkalkulation.

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
status-stopped = angehalten: { $failure }; gezeigt wird der letzte gültige Zustand

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
key-duplicate = Das ausgewählte Objekt duplizieren
key-play-pause = Start oder Pause
key-step = Einen Schritt vor
key-step-back = Einen Schritt zurück im Lauf
key-next-turn = Nächster Umkehrpunkt des gewählten Teilchens
key-previous-turn = Voriger Umkehrpunkt des gewählten Teilchens
key-reset = Zurück zur gebauten Szene
key-fit = Die Ansicht an die Szene anpassen
key-stopwatch = Stoppuhr
key-inspector = Den Inspektor zeigen oder verbergen
key-graphs = Die Diagramme zeigen oder verbergen
key-projector = Projektormodus
key-help = Diese Liste der Tasten
key-next-region = Der Fokus zum nächsten Bereich: Menü, Werkzeugleiste, Zeichenfläche, Inspektor, Diagramme, Zeitleiste
key-previous-region = Der Fokus zum vorigen Bereich
canvas-key-focus = Der Zeichenfläche die Tastatur geben
canvas-launch = { $speed } unter { $angle }°
canvas-key-cycle = Das nächste / vorige Objekt auswählen
canvas-key-move = Das ausgewählte Teilchen oder die Rampe um einen Rasterschritt verschieben
canvas-key-fine = Um ein Zehntel eines Rasterschritts verschieben
canvas-key-enter = Ein Objekt des aktuellen Werkzeugs in der Mitte der Ansicht hinzufügen (eine Feder, Stange oder einen Faden vom ausgewählten Teilchen aus)
canvas-key-escape = Die Tastatur zurückgeben; Tab geht dann zum nächsten Bedienelement
canvas-key-instrument-enter = Mit dem Maßband (M) oder dem Winkelmesser (A): vom ausgewählten Teilchen zu den nächsten legen, oder in die Mitte der Ansicht
canvas-key-instrument-tab = Mit dem Maßband oder dem Winkelmesser: das Ende oder den Punkt wählen, den die Pfeiltasten bewegen
canvas-key-instrument-move = Mit der Sonde, dem Maßband oder dem Winkelmesser: (den gewählten Punkt) um ein Zehntel eines Rasterschritts verschieben; Umschalt ein Hundertstel
canvas-key-add = Ein Objekt zur Auswahl hinzufügen oder herausnehmen
canvas-key-box = Auswählen, was in einem von leerer Fläche aus gezogenen Rahmen liegt

## Readouts and graphs
readout-heading = Energie und Impuls
readout-failed = Der Lauf ist gescheitert: die Werte seiner letzten gültigen Probe.
readout-potential = potentiell (J)
readout-potential-field = potentiell: Höhe, m g h (J)
readout-potential-springs = potentiell: Federn (J)
readout-potential-gravitation = potentiell: Gravitation (J)
readout-potential-electrostatic = potentiell: elektrostatisch (J)
readout-potential-own = potentiell: eigene Kräfte (J)
readout-press-play = vor dem Start
readout-at = Bei t = { $time }
readout-kinetic = kinetisch (J)
readout-total = gesamt (J)
readout-total-at-play = gesamt beim Start (J)
readout-damping = durch Dämpfung entzogen (J)
readout-friction = durch Reibung entzogen (J)
readout-impacts = durch Stöße entzogen (J)
readout-drag = durch Luftwiderstand entzogen (J)
readout-motors = von Motoren zugeführt (J)
readout-ties = Arbeit der Stangen und Fäden (J)
readout-error = numerischer Fehler
readout-momentum = Impuls (kg·m/s)
bar-kinetic = kinetisch
bar-damping = Dämpfung entzog
bar-friction = Reibung entzog
bar-impacts = Stöße entzogen
bar-drag = Luftwiderstand entzogen
bar-motors = Motoren zugeführt
bar-total-at-play = gesamt beim Start
bars-title = Energiebalken
bars-hint = Jede Energieart im selben Maßstab; die Zahlen stehen in der Tabelle darüber
impacts-title = Stöße ({ $count })
impacts-none = Noch keine Stöße.
impacts-time = t (s)
impacts-particle = Teilchen
impacts-hit = traf
impacts-impulse = Kraftstoß (N·s)
impacts-lost = verloren (J)
impacts-a-ramp = eine Rampe
impacts-wall = Wand
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
graph-save-png-hint = Diesen Graphen als druckbare Abbildung speichern: 1200 × 800 Pixel, mit Titel, Achsen, Zahlen, Einheiten und Legende
graph-save-svg = SVG speichern…
graph-save-svg-hint = Diesen Graphen als druckbare Abbildung im SVG-Format speichern: sie lässt sich beliebig skalieren
graph-press-play = Start drücken: das Diagramm füllt sich vom Beginn des Laufs an.

## Announcements for screen readers
announce-impact = Bei { $time } s stieß { $particle } an { $other }.{ $more ->
    [0] {""}
    [one] {" "}Dazu 1 weiterer Stoß seit der letzten Meldung.
   *[other] {" "}Dazu { $more } weitere Stöße seit der letzten Meldung.
}
announce-wall = die Wand
announce-stretch = Bei { $time } s ist die Feder { $spring } voll gedehnt, { $length } m.

## Instruments, tools, the timeline, the stopwatch, files, the inspector, links
instrument-tape = Maßband
instrument-probe = Feldsonde
instrument-protractor = Winkelmesser
instrument-tape-hint = Zwischen zwei Punkten ziehen, um Abstand und Richtung zu messen; ein Ende auf einem Teilchen folgt ihm (M)
instrument-probe-hint = Einen Punkt anklicken, um dort Gravitations- und elektrisches Feld und Potential abzulesen; die Pfeiltasten verschieben die Sonde (P)
instrument-protractor-hint = Vom Scheitel entlang des ersten Schenkels ziehen, dann noch einmal für den zweiten: der Winkel zwischen ihnen; Enden auf Teilchen folgen ihnen (A)
instrument-probe-at = bei { $position } m
instrument-probe-vector = { $vector } { $unit }, Betrag { $size } { $unit }
instrument-probe-gravitational-potential = Gravitationspotential { $value } J/kg
instrument-probe-electric-potential = elektrisches Potential { $value } V
tool-select-hint = Objekte auswählen und verschieben; die Spitze eines Geschwindigkeitspfeils ziehen, um die Geschwindigkeit zu setzen; leeren Raum ziehen, um die Ansicht zu verschieben (1)
tool-particle-hint = Auf die Zeichenfläche klicken, um ein Teilchen zu setzen (2)
tool-spring-hint = Von einem Teilchen zu einem anderen ziehen, oder in leeren Raum für einen festen Punkt (3)
tool-rod-hint = Eine starre Stange: von einem Teilchen zu einem anderen ziehen, oder in leeren Raum für einen festen Punkt (5)
tool-string-hint = Ein Faden (locker, wenn kürzer): von einem Teilchen zu einem anderen ziehen, oder in leeren Raum für einen festen Punkt (6)
tool-ramp-hint = Ziehen, um eine Rampe zu zeichnen (4)
stopwatch-by-hand = von Hand
stopwatch-gate = Durchgang am Maßband
stopwatch-on-play = Start der Wiedergabe
stopwatch-impact = ein Stoß
stopwatch-event = ein Ereignis
notice-invalid-values = Läuft nicht: einige eingegebene Werte sind ungültig (rot im Inspektor). Bitte zuerst korrigieren:
    { $reasons }
notice-nothing-to-export = Noch nichts zu exportieren: zuerst Abspielen drücken.
notice-paste-no-scene = Nichts eingefügt: die Zwischenablage enthält keinen Szenen-Text ({ $reason })
notice-exported = { $rows } Messpunkte nach { $path } exportiert.
notice-settings-not-kept = Die Einstellungen konnten nicht gespeichert werden: { $reason }
failure-reset = Szene zurücksetzen
status-physics-time = Physik { $ms } ms pro Bild
status-physics-time-hint = Rechenzeit, die in jedem Bild auf die Simulation entfällt
inspector-title = Inspektor
timeline-step-back = Schritt zurück
timeline-before-play = Die Zeitmaschine: Start drücken, dann zurückgehen oder zu jedem Moment des Laufs springen
timeline-step-back-hint = Einen Zeitschritt im Lauf zurück (,)
timeline-slider-hint = Zu einem beliebigen Moment des Laufs ziehen: er wird genau so gezeigt, wie er war
timeline-time = t = { $now } s von { $last } s
timeline-to-end = Zum Ende
timeline-to-end-hint = Zurück dorthin, wo der Lauf steht
timeline-previous-turn = « Umkehr
timeline-next-turn = Umkehr »
timeline-turn-hint = Der vorige oder nächste Umkehrpunkt des gewählten Teilchens ([ und ]): wo x oder y seiner Geschwindigkeit durch 0 geht, genau bestimmt
timeline-previous-impact = « Stoß
timeline-next-impact = Stoß »
timeline-impact-hint = Der vorige oder nächste Stoß des Laufs, zu seinem bestimmten Zeitpunkt
timeline-go-to = gehe zu
timeline-go-to-hint = Einen Zeitpunkt des Laufs eingeben (1.5, 1500 ms) und Enter drücken: er wird genau gezeigt
timeline-no-turn = Dort kein Umkehrpunkt: wählen Sie ein Teilchen, dessen Geschwindigkeit im Lauf durch 0 geht.
timeline-no-impact = Dort kein Stoß im Lauf.
timeline-edit-from-here = Von hier bearbeiten
timeline-edit-from-here-hint = Diesen Moment zum Anfang der Szene machen (Orte, Geschwindigkeiten und Zeit), um etwas zu ändern und eine neue Zukunft abzuspielen; rückgängig zu machen
stopwatch-title = Stoppuhr
stopwatch-stopped = angehalten
stopwatch-armed = wartet auf den Start
stopwatch-running = läuft
stopwatch-stop = Stopp
stopwatch-start = Start
stopwatch-reset = Stoppuhr zurücksetzen
stopwatch-start-on = starten
stopwatch-stop-on = anhalten
stopwatch-period-at-gate = Periode an der Schranke
stopwatch-period-at-gate-hint = Start beim 1. Durchgang durch das Maßband, Halt beim 3.: eine volle Periode eines Pendels, das durch eine Schranke an seiner Aufhängung schwingt
stopwatch-between-impacts = zwischen Stößen
stopwatch-between-impacts-hint = Start beim 1. Stoß, Halt beim 2.: der Flug eines Sprungs
stopwatch-nth = Nr.
stopwatch-nth-hint = Das wievielte Auftreten, ab Start gezählt: eine volle Periode eines Pendels ist der 1. und der 3. Durchgang durch die Senkrechte
stopwatch-event-label = Ereignis
stopwatch-event-hint = GRÖSSE crosses WERT, wahlweise up oder down: rod.angle crosses 0 down, bob.vx crosses 0
stopwatch-lap-mode = Runden
stopwatch-lap-mode-hint = Weiterlaufen: jeder Halt ist eine Runde, bis Stopp gedrückt wird; die Runden und ihr Mittel werden aufgelistet
stopwatch-mean = Mittel { $mean } s aus { $laps } Runden
stopwatch-note = Simulierte Zeit. Jeder Zeitpunkt wird innerhalb des Schritts bestimmt: Stöße, die Lichtschranke (ein Teilchenmittelpunkt kreuzt das Maßband) und Ereignisse auf eine Mikrosekunde oder besser.
graph-ask-hint = Fügt der Lektion eine Frage hinzu, deren Antwort diese Periode ist (die Simulation prüft die Antworten der Klasse daran)
graph-ask-prompt = Wie groß ist die Periode von { $quantity }?
stopwatch-ask = Danach fragen
stopwatch-ask-hint = Fügt der Lektion eine Frage hinzu, deren Antwort diese Messung ist: die Zeit von Play bis zum Ereignis (die Simulation prüft die Antworten der Klasse daran)
stopwatch-ask-prompt = Wie lange nach Play geschieht dies: { $event }?
stopwatch-asked = Frage { $id } wurde der Lektion hinzugefügt; Frage und Toleranz lassen sich in der Szenendatei ändern.
edit-ask = der Lektion eine Frage hinzufügen
lesson-untitled = Lektion
notice-picture-saved = Bild unter { $path } gespeichert.
file-ok = OK
file-ok-hint = Diese Meldung schließen (Enter)
file-changed-title = Auf der Festplatte geändert
file-changed-body = „{ $path }“ wurde seit dem Öffnen auf der Festplatte geändert. Überschreiben?
file-overwrite = Überschreiben
file-overwrite-hint = Die Datei auf der Festplatte durch diese Szene ersetzen
file-cancel = Abbrechen
file-keep-hint = Die Datei auf der Festplatte behalten; stattdessen unter einem anderen Namen speichern
file-recover-title = Ungespeicherte Arbeit wiederherstellen
file-recover-body = NewtonLab wurde beim letzten Mal mit ungespeicherten Änderungen geschlossen. Wiederherstellen?
file-recover-body-path = NewtonLab wurde beim letzten Mal mit ungespeicherten Änderungen an „{ $path }“ geschlossen. Wiederherstellen?
file-recover = Wiederherstellen
file-recover-hint = Die ungespeicherte Arbeit öffnen
file-discard = Verwerfen
file-discard-hint = Die ungespeicherte Arbeit wegwerfen
file-unsaved-title = Ungespeicherte Änderungen
file-unsaved-body = „{ $title }“ hat ungespeicherte Änderungen. Zuerst speichern?
file-discard-changes = Änderungen verwerfen
file-discard-changes-hint = Die ungespeicherten Änderungen verlieren
file-keep-editing-hint = Weiter bearbeiten
file-verb-open = Öffnen
file-verb-save = Speichern
file-verb-export = Exportieren
file-title-open = Eine Szene öffnen
file-title-save = Die Szene speichern
file-title-csv = Den Graphen als CSV exportieren
file-title-png = Das Bild als PNG speichern
file-title-svg = Die Abbildung als SVG speichern
file-folder = Ordner
file-folder-hint = Der Ordner
file-parent = .. (übergeordneter Ordner)
file-parent-hint = Der übergeordnete Ordner
file-name = Dateiname
file-name-hint = Der Name der Datei ({ $extensions })
file-submit-hint = Diese Datei: { $verb } (Enter)
file-close-hint = Schließen, ohne etwas zu tun
inspector-use-cartesian = x, y verwenden
inspector-use-polar = polar verwenden
inspector-switch-hint = Diesen Vektor in der anderen Form zeigen (der Wert bleibt)
inspector-running = Läuft: Zurücksetzen (R), um die Szene zu bearbeiten.
inspector-selected = Ausgewählt
inspector-selected-at-start = Ausgewählt: wie die Szene beginnt
inspector-delete = Löschen
inspector-delete-hint = Das ausgewählte Objekt entfernen (Entf)
inspector-world = Welt
inspector-simulation = Simulation
inspector-live = Live: { $name }
inspector-tension = Spannkraft
inspector-tension-hint = Die Kraft, die sie trägt: Zug ist positiv; 0, wenn locker
inspector-work-done = verrichtete Arbeit
inspector-no-work = 0 J (eine Zwangsbedingung verrichtet keine Arbeit)
inspector-live-position = Ort
inspector-live-velocity = Geschwindigkeit
inspector-live-acceleration = Beschleunigung
inspector-live-speed = Geschwindigkeitsbetrag
inspector-live-kinetic-energy = kinetische Energie
inspector-live-momentum = Impuls
inspector-live-spin = Winkelgeschwindigkeit
inspector-live-angle = Winkel
inspector-live-rotational = davon Rotation
inspector-live-angular-momentum = Drehimpuls
inspector-pair-forces-direct = direkt (jedes Paar, exakt)
inspector-pair-forces-tree = Baum (Barnes–Hut, für Tausende)
inspector-arithmetic-hint = Rechnungen und Einheiten werden umgerechnet: 2*pi, sqrt(2)/2, 30 km/h, 5 cm, 250 g; Dezimalkomma oder -punkt
inspector-polar-angle = Winkel
inspector-polar-angle-hint = Grad, gegen den Uhrzeigersinn ab +x
inspector-nothing-selected = Nichts ausgewählt: ein Objekt auf der Zeichenfläche anklicken.
inspector-ramp-angle = Neigung
inspector-ramp-angle-hint = Die Richtung von seinem Ende „from“ zu seinem Ende „to“, in Grad gegen den Uhrzeigersinn von +x (−30 fällt nach rechts); die Eingabe dreht die Rampe um „from“
inspector-ramp-length = Länge
inspector-ramp-length-hint = Der Abstand seiner Enden; die Eingabe verschiebt „to“ entlang der Neigung
inspector-on-ramp = auf Rampe
inspector-on-ramp-hint = Die Rampe, auf die dieses Teilchen gesetzt wird
inspector-put-on-ramp = Daraufsetzen
inspector-put-on-ramp-hint = Das Teilchen so verschieben, dass es die Oberseite der Rampe berührt, im unten angegebenen Abstand von ihrem Ende „from“
inspector-along-ramp = entlang
inspector-along-ramp-hint = Wie weit entlang der Rampe, von ihrem Ende „from“ aus, das Teilchen sie berührt; die Eingabe setzt es dorthin
inspector-inertia-presets = dreht sich als
inspector-inertia-point = Punkt
inspector-inertia-point-hint = Trägheit 0: dreht sich nie, keine Reibung bei Stößen
inspector-inertia-disc = Vollscheibe
inspector-inertia-disc-hint = Trägheit 0,5: I = ½ m r²; rollt eine Schräge mit ⅔ g sin θ hinab
inspector-inertia-ring = Ring
inspector-inertia-ring-hint = Trägheit 1: I = m r²; rollt eine Schräge mit ½ g sin θ hinab
link-too-long = Dieser Link ist zu lang für eine NewtonLab-Szene ({ $length } Zeichen; die Grenze ist { $limit }).
link-no-example = Dieser Link nennt eine eingebaute Szene, die es nicht gibt: '{ $name }'.
link-not-base64 = Dieser Link ist beschädigt: seine Szene ist kein gültiges Base64 (wurde er gekürzt oder bearbeitet?).
link-too-large = Die Szene dieses Links ist entpackt größer als { $megabytes } MB; sie wurde nicht geöffnet.
link-not-unpacked = Dieser Link ist beschädigt: seine Szene ließ sich nicht entpacken (wurde er gekürzt oder bearbeitet?).
link-not-text = Dieser Link ist beschädigt: seine Szene ist kein Text.
menu-share-link = Link teilen…
menu-share-link-hint = Ein Link, der diese Szene samt Lektion in der Browser-Version öffnet: für eine E-Mail oder die Seite der Klasse
menu-open-link = Link öffnen…
menu-open-link-hint = Die Szene eines hier eingefügten NewtonLab-Links öffnen
link-share-title = Link teilen
link-open-title = Link öffnen
link-address = Adresse der Browser-Version, die Ihre Klasse öffnet:
link-address-hint = Wo der Ordner von scripts/build-web.sh bereitgestellt wird (ein Schulserver, GitHub Pages); die Szene steckt im Link selbst und geht nie an einen Server.
link-length = { $length } Zeichen insgesamt
link-copy = Link kopieren
link-copied = Der Link zu dieser Szene ist in der Zwischenablage.
link-paste = Einen Link zu einer NewtonLab-Szene einfügen:
link-open = Öffnen
link-untitled = Verlinkte Szene
link-not-newtonlab = Das ist kein Link zu einer NewtonLab-Szene: Er hat keinen Teil #scene= oder #example=.
link-scene-too-large = Diese Szene ist zu groß für einen Link ({ $length } Zeichen; höchstens { $limit }): Speichern Sie sie stattdessen als Datei.

## The scene checker (the physics crate): problems in a scene file or a typed value
scene-the-scene = Szene
scene-named = { $kind ->
        [particle] Teilchen
        [spring] Feder
        [rod] Stange
        [string] Faden
        [ramp] Rampe
        [body] Körper
        [pin] Stift
        [hinge] Scharnier
        [pulley] Rolle
        [force] Kraft
        [series] Messreihe
        [slider] Schieberegler
        [question] Frage
       *[graph] Graph
    } '{ $name }'
scene-numbered = { $kind ->
        [particle] Teilchen
        [spring] Feder
        [rod] Stange
        [string] Faden
        [ramp] Rampe
        [body] Körper
        [pin] Stift
        [hinge] Scharnier
        [pulley] Rolle
        [force] Kraft
        [series] Messreihe
        [slider] Schieberegler
        [question] Frage
       *[graph] Graph
    } #{ $number }
scene-not-finite = { $field } muss eine endliche Zahl sein, nicht { $value }
scene-not-positive = { $field } muss größer als 0 sein, nicht { $value }
scene-negative = { $field } muss 0 oder mehr sein, nicht { $value }
scene-not-fraction = { $field } muss zwischen 0 und 1 liegen, nicht { $value }
scene-too-large = { $field } { $value } ist zu groß für eine verlässliche Simulation: Zahlen in einer Szene sind 0 oder zwischen 1e-100 und 1e100 groß, damit Kräfte und Energien im Bereich von f64 bleiben
scene-too-small = { $field } { $value } ist zu klein für eine verlässliche Simulation: Zahlen in einer Szene sind 0 oder zwischen 1e-100 und 1e100 groß, damit Kräfte und Energien im Bereich von f64 bleiben
scene-vector-not-finite = { $field } muss endliche Komponenten haben
scene-bounds-order = bounds: min muss links unterhalb von max liegen, nicht min [{ $a }, { $b }] und max [{ $c }, { $d }]
scene-name-empty = name darf nicht leer sein
scene-name-taken = der Name '{ $name }' ist schon vergeben an { $earlier }; Namen müssen eindeutig sein
scene-drag-too-strong = lineare Reibung { $a } kg/s bei { $b } kg bremst das Teilchen alle { $c } s um den Faktor e, schneller als ein Zeitschritt von { $d } s folgen kann (das Verfahren erzeugte Energie aus dem Nichts): einen Zeitschritt von höchstens { $c } s wählen, oder dopri5
scene-drag-twice = sowohl ein quadratischer Luftwiderstand c ({ $a } kg/m) als auch ein Widerstandsbeiwert ({ $b }): eines von beiden angeben (der Beiwert ergibt c = ½ ρ C_d π r²)
scene-outside-bounds = position [{ $a }, { $b }] setzt das Teilchen (Radius { $c }) außerhalb der Weltgrenzen
scene-ends-fixed = { $kind ->
        [spring] eine Feder
        [rod] eine Stange
       *[string] ein Faden
    } braucht an mindestens einem Ende ein bewegliches Teilchen; beide Enden sind fest
scene-no-particle = { $field }: es gibt kein Teilchen namens '{ $name }'
scene-ends-points = { $kind ->
        [spring] eine Feder
        [rod] eine Stange
       *[string] ein Faden
    } braucht an mindestens einem Ende ein Teilchen; beide Enden sind feste Punkte
scene-same-particle = beide Enden sind das Teilchen '{ $name }'; { $kind ->
        [spring] eine Feder
        [rod] eine Stange
       *[string] ein Faden
    } verbindet zwei verschiedene Dinge
scene-graph-no-particle = { $field }: '{ $text }' nennt kein Teilchen; es gibt kein Teilchen '{ $name }'
scene-graph-no-tie = { $field }: '{ $text }' nennt keine Stange und keinen Faden; es gibt keine(n) namens '{ $name }'
scene-graph-no-link = { $field }: „{ $text }“ nennt keine Stange, keinen Faden und keine Feder; es gibt keine namens „{ $name }“
scene-graph-time-on-y = y: die Zeit gehört auf die x-Achse (x = "t")
scene-follow-unknown = follow: es gibt kein Teilchen '{ $name }'; einem Teilchennamen folgen, oder "all"
scene-trigger-unknown = muss eines von { $words } sein, erhalten: '{ $got }'
scene-instrument-ends = hat { $least } bis { $most } Enden, jedes ein Punkt [x, y] oder der Name eines Teilchens; erhalten: { $got }
scene-count-not-whole = muss eine ganze Zahl ab 1 sein (das wievielte Ereignis), erhalten: { $got }
scene-instrument-no-particle = { $field }: es gibt kein Teilchen namens '{ $name }', dem ein Ende folgen könnte
scene-stopwatch-stop-on-play = stop: Play kann die Stoppuhr starten, nicht anhalten
scene-stopwatch-gate-no-tape = { $field }: die Lichtschranke ist die Strecke des Maßbands; legen Sie ein Maßband in [instruments]
scene-stopwatch-no-event = event: eine Stoppuhr, die ein Ereignis startet oder anhält, braucht das Ereignis (bob.x crosses 0 up)
scene-stopwatch-count = { $field } muss eine ganze Zahl ab 1 sein
scene-quantity-of-particle = „{ $text }“: eine Größe eines Teilchens ist eine von { $keys }; die einer Stange, eines Fadens oder einer Feder ist angle oder length, die einer Stange oder eines Fadens auch tension
scene-not-a-quantity = „{ $text }“ ist keine Größe: schreiben Sie t, NAME.x (oder .y, .vx, .vy, .speed, .ax, .ay, .kinetic_energy; turning: .angle, .spin), STANGE.angle (oder .length, .tension) oder eine von { $keys }
quantity-no-particle = „{ $text }“: es gibt kein Teilchen namens „{ $name }“ (die Teilchen: { $names })
quantity-no-link = „{ $text }“: es gibt keine Stange, keinen Faden und keine Feder namens „{ $name }“ (vorhanden: { $names })
quantity-no-joint = „{ $text }“: es gibt keinen Stift und kein Scharnier namens „{ $name }“ (vorhanden: { $names })
quantity-no-pulley = „{ $text }“: es gibt keine Rolle namens „{ $name }“ (vorhanden: { $names })
quantity-spring-tension = „{ $text }“: „{ $name }“ ist eine Feder; ihr Winkel und ihre Länge lassen sich lesen, eine Spannkraft nur bei Stangen und Fäden
event-malformed = „{ $text }“ ist kein Ereignis: schreiben Sie GRÖSSE crosses WERT, wahlweise gefolgt von up oder down (Ball.y crosses 0 down)
event-value = „{ $text }“: „{ $value }“ ist keine endliche Zahl, die überschritten werden kann
setting-object = „{ $text }“ nennt kein Objekt der Szene: schreiben Sie OBJEKT.schlüssel (Ball.mass, Ball.velocity.angle), world.schlüssel oder simulation.schlüssel
setting-key = „{ $text }“: dort gibt es keine Zahl dieses Namens (die Schlüssel sind die der Szenendatei: mass, velocity, gravity, time_step…)
setting-part = „{ $text }“: ein Vektor wird über einen Teil variiert, .x, .y, .magnitude oder .angle (Grad), eine Zahl über keinen
vary-malformed = „{ $text }“ ist kein Bereich: schreiben Sie FELD=VON:BIS:SCHRITT (Ball.velocity.angle=10:80:5)
series-too-many-runs = { $runs } Läufe, mehr als { $most }: gröbere Schritte oder weniger Werte wählen
series-too-many-steps = ein Lauf bis { $until } s bräuchte { $steps } Schritte, mehr als { $most }: einen größeren Zeitschritt oder einen kürzeren Lauf wählen
series-too-much-work = seine { $runs } Läufe bräuchten insgesamt { $work } Teilchen-Schritte, mehr als { $most } (Stunden Arbeit): weniger Werte, einen größeren Zeitschritt oder einen kürzeren Lauf wählen
vary-too-many = „{ $text }“ hat { $count } Werte, mehr als eine Million: einen größeren Schritt wählen
vary-empty = „{ $text }“ hat keine Werte: der Schritt darf nicht 0 sein und muss von VON nach BIS führen
measure-malformed = „{ $text }“ ist keine Messung: schreiben Sie GRÖSSE at EREIGNIS [#N], t at EREIGNIS, max GRÖSSE, min GRÖSSE, period GRÖSSE oder GRÖSSE at T
measure-instant = der Zeitpunkt { $instant } s liegt außerhalb des Laufs, { $from } s bis { $until } s
measure-no-period = weniger als drei Maxima ({ $count }) bis { $until } s: keine Periode (mindestens zwei Zyklen werden verglichen)
measure-irregular-period = seine { $count } Maxima bis { $until } s wiederholen sich in keinem regelmäßigen Zyklus: keine Periode bestimmbar
measure-no-event = „{ $event }“ geschah bis { $until } s { $count }-mal, nicht { $nth }-mal
measure-none = bis { $until } s nichts gemessen
theory-unreadable = „{ $text }“ ist kein Ausdruck: schreiben Sie Arithmetik in x (dem variierten Wert) und den Konstanten der Szene, etwa v0^2*sin(2*a)/g
theory-unknown-name = eine Theorie kann { $names } nennen, nicht „{ $name }“
scene-series-until = until muss eine Zahl nach dem Start der Szene sein, erhalten: { $until }
sweep-every-run-failed = jeder Lauf der Reihe ist gescheitert (die Gründe stehen oben)
sweep-run-failed = Lauf { $run }: { $why }
sweep-no-measure = Lauf { $run }: „{ $measure }“: { $why }
scene-unsatisfiable = die Länge { $length } m lässt sich zusammen mit den anderen Stangen und Fäden an ihren Enden nicht einhalten (die nächste Anordnung verfehlt sie um { $miss } m); eine Länge oder ein Ende ändern
scene-at-line-column = Zeile { $line }, Spalte { $column }
scene-at-line = Zeile { $line }
scene-problems-found = { $source }: { $count ->
        [1] 1 Problem
       *[other] { $count } Probleme
    } gefunden:
scene-got-bool = wahr oder falsch
scene-got-number = eine Zahl
scene-got-text = Text
scene-got-list = eine Liste
scene-got-table = eine Tabelle
scene-got-date = ein Datum
scene-bad-toml = das ist kein gültiges TOML: { $error }
scene-bad-json = das ist kein gültiges JSON: { $error }
scene-not-a-table = { $label } muss eine Tabelle sein, nicht { $got }
scene-keys-here = die Schlüssel hier sind { $keys }
scene-did-you-mean = war '{ $key }' gemeint?
scene-unknown-key = { $label }: unbekannter Schlüssel '{ $key }'; { $hint }
scene-required = { $label }: { $key } ist erforderlich
scene-the-whole = die Szene
scene-version-unsupported = Szene: Version { $version } wird nicht unterstützt; dieses NewtonLab liest Version { $supported }
scene-version-required = Szene: version ist erforderlich; `version = 1` an den Anfang der Datei schreiben
scene-not-a-list = Szene: '{ $key }' muss eine Liste von [[{ $key }]]-Tabellen sein, nicht { $got }
scene-must-be-finite = muss eine endliche Zahl sein, nicht { $got }
scene-must-be-number = muss eine Zahl sein, nicht { $got }
scene-must-be-bool = muss true oder false sein, nicht { $got }
scene-must-be-text = muss Text in Anführungszeichen sein, nicht { $got }
scene-must-be-quantities = muss eine Liste von Größen in Anführungszeichen sein, wie ["A.x", "total_energy"], nicht { $got }
scene-vector-length = muss { $cartesian } oder { $polar } sein, nicht eine Liste von { $count } Zahlen
scene-vector-extra = muss { $cartesian } oder { $polar } sein; '{ $key }' gehört nicht zu einem Vektor
scene-vector-polar = muss { $cartesian } oder { $polar } sein; ein polarer Vektor braucht magnitude und angle
scene-vector-got = muss { $cartesian } oder { $polar } sein, nicht { $got }
scene-bounds-got = muss { $form } sein, nicht { $got }
scene-bounds-extra = muss { $form } sein; '{ $key }' gehört nicht zu bounds
scene-bounds-both = muss { $form } sein; min und max werden beide gebraucht
scene-endpoint-point = muss der Name eines Teilchens oder ein Punkt sein; als Punkt { $reason }
scene-endpoint-got = muss der Name eines Teilchens oder ein Punkt [x, y] sein, nicht { $got }
scene-not-integrator = '{ $name }' ist kein Integrator; einen von { $names } wählen
scene-not-pair-forces = '{ $name }' ist keine Art, Paarkräfte zu summieren; direct oder tree wählen
scene-not-colour = muss eine Farbe wie "#d94f4f" sein, nicht "{ $text }"

## The command line
run-non-finite = bei t = { $time } s erreichte das Teilchen '{ $particle }' einen nicht endlichen Ort oder eine nicht endliche Geschwindigkeit (zwei Körper kamen sich zu nahe, oder der Zeitschritt ist für die Kräfte zu groß)
run-value-not-finite = bei t = { $time } s ist { $quantity } gleich { $value }, keine Zahl, die eine Zeile fassen kann: zwei Körper sind sich so nahe, dass die Kraft zwischen ihnen überläuft
run-step-too-small = bei t = { $time } s brauchte der adaptive Integrator einen zu kleinen Schritt, um mit der Toleranz { $tolerance } voranzukommen; die Toleranz lockern oder prüfen, ob Körper einander durchdringen
run-too-many-steps = bei t = { $time } s brauchte es mehr als { $limit } adaptive Schritte bis { $target } s (der Zeitschritt von { $step } s ist für die Bewegung dieser Szene viel zu lang); einen kleineren time_step wählen
cli-no-window = die App konnte kein Fenster öffnen: { $error }
    (die Befehle ohne Fenster gehen auch so: siehe `newtonlab --help`)
cli-check-ok = { $source }: in Ordnung ({ $particles } Teilchen, { $springs } Federn, { $ramps } Rampen, Integrator { $integrator }, Zeitschritt { $step } s)
cli-check-tree = Hinweis: die Gravitation wird mit dem Barnes–Hut-Baum summiert (Öffnungswinkel { $angle })
cli-check-tree-and-charges = Hinweis: die Gravitation wird mit dem Barnes–Hut-Baum summiert (Öffnungswinkel { $angle }); die Coulombkräfte zwischen ihren { $charged } geladenen Teilchen werden direkt summiert, Paar für Paar
cli-until-not-finite = --until muss eine endliche Zahl von Sekunden sein, nicht { $until }
cli-every-invalid = --every muss eine endliche Zahl von Sekunden größer als 0 sein, nicht { $every }
cli-event-invalid = --events: { $reason }
cli-column-invalid = --column: { $reason }
cli-until-negative = --until muss 0 oder mehr Sekunden sein, nicht { $until }
cli-until-before-start = --until { $until } liegt vor der start_time { $start } s der Szene; ein Lauf geht von seinem Anfang vorwärts
cli-too-many-rows = --until { $until } mit --every { $every } würde { $rows } Zeilen mit je { $columns } Zahlen schreiben, mehr als { $most } Zahlen; ein größeres --every wählen oder --no-limit angeben
cli-too-many-steps = --until { $until } bei einem Zeitschritt von { $step } s bräuchte { $steps } Schritte, mehr als { $most }; einen größeren time_step oder ein kürzeres --until wählen oder --no-limit angeben
cli-cannot-create = die Ausgabedatei '{ $path }' lässt sich nicht anlegen: { $error }
cli-cannot-write-csv = das CSV lässt sich nicht schreiben: { $error }
cli-cannot-save-state = der Zustand lässt sich nicht nach '{ $path }' schreiben: { $error }
cli-sampling-note = Hinweis: --every { $every } s ist kein ganzzahliges Vielfaches des Zeitschritts ({ $step } s): jeder Messpunkt verkürzt einen Schritt, um genau auf ihm zu landen, also rechnet dieser Lauf mit einem kleineren wirksamen Schritt als die Szene, und seine Zahlen weichen leicht von einem Lauf ab, der bei einem Vielfachen von { $step } s misst
cli-cannot-create-log = das Stoßprotokoll '{ $path }' lässt sich nicht anlegen: { $error }
cli-no-example = es gibt keine eingebaute Szene '{ $name }'; die Beispiele sind: { $names }
cli-cannot-read = die Szenendatei '{ $source }' lässt sich nicht lesen: { $error }

## The inspector's fields (English: the field table's words, physics::fields; the file's keys stay as they are)
field-world-gravity = Schwerkraft
field-world-gravity-help = Das homogene Feld
field-world-gravitation = Gravitation zwischen Teilchen
field-world-gravitation-help = Newtons Anziehung mit dem umgekehrten Quadrat des Abstands zwischen jedem Paar
field-world-gravitational-constant = G
field-world-gravitational-constant-help = Die Gravitationskonstante (der Wert des Artikels)
field-world-electrostatics = Elektrostatik
field-world-electrostatics-help = Das Coulombsche Gesetz zwischen geladenen Teilchen
field-world-coulomb-constant = k
field-world-coulomb-constant-help = Die Coulomb-Konstante
field-world-softening = Glättung
field-world-softening-help = Plummer-Glättungslänge ε von Gravitation und Coulomb-Kraft: Kraft ∝ r/(r² + ε²)^(3/2), endlich bei nahen Begegnungen
field-world-air-density = Luftdichte
field-world-air-density-help = ρ, gegen die der Widerstandsbeiwert eines Teilchens drückt: ½ ρ C_d π r² v² (Luft bei 20 °C: 1,2)
field-world-magnetic-field = Magnetfeld
field-world-magnetic-field-help = B_z, aus dem Bildschirm heraus positiv: eine Kraft q v × B auf jedes bewegte geladene Teilchen
field-world-collisions = Stöße zwischen Teilchen
field-world-collisions-help = Teilchen stoßen und liegen aufeinander; false: sie durchdringen einander (Rampen und Grenzen halten sie weiter auf)
field-world-restitution = Stoßzahl
field-world-restitution-help = Stöße zwischen Teilchen: 0 (klebend) bis 1 (elastisch)
field-world-friction = Reibung zwischen Teilchen
field-world-friction-help = μ zwischen sich drehenden Teilchen bei Stößen: ihre Berührpunkte haften bis zum μ-fachen des Normalstoßes
field-world-bounds = Grenzen
field-world-bounds-help = Ein reflektierender Kasten um die Welt
field-simulation-integrator = Integrator
field-simulation-integrator-help = Wie die Bewegung in der Zeit integriert wird: euler, semi-implicit-euler, verlet, rk4, pefrl, dopri5
field-simulation-time-step = Zeitschritt
field-simulation-time-step-help = Der Schritt (dopri5: der größte Schritt)
field-simulation-tolerance = Toleranz
field-simulation-tolerance-help = Nur dopri5: erlaubter Fehler pro Schritt, relativ und absolut
field-simulation-time-scale = Zeitmaßstab
field-simulation-time-scale-help = Simulierte Sekunden pro echter Sekunde beim Abspielen in der App
field-simulation-pair-forces = Paarkräfte
field-simulation-pair-forces-help = Wie die Gravitation summiert wird: direct (jedes Paar, exakt) oder tree (Barnes–Hut, für Tausende von Körpern)
field-simulation-opening-angle = Öffnungswinkel
field-simulation-opening-angle-help = Nur tree: eine Gruppe der Größe s im Abstand d wirkt als ein Körper, wenn s/d darunter liegt
field-simulation-start-time = Startzeit
field-simulation-start-time-help = Der Zeitpunkt, den der Zustand der Szene beschreibt (ein gespeicherter Zustand behält seine Zeit)
field-particle-mass = Masse
field-particle-mass-help = Masse, größer als 0
field-particle-radius = Radius
field-particle-radius-help = Radius, größer als 0
field-particle-charge = Ladung
field-particle-charge-help = Elektrische Ladung
field-particle-position = Ort
field-particle-position-help = Ort
field-particle-velocity = Geschwindigkeit
field-particle-velocity-help = Geschwindigkeit
field-particle-acceleration = Beschleunigung
field-particle-acceleration-help = Eine konstante zusätzliche Beschleunigung zu allen Kräften
field-particle-fixed = fest
field-particle-fixed-help = Ein festes Teilchen bewegt sich nie; es zieht trotzdem an, stößt ab und wird getroffen
field-particle-linear-drag = Luftwiderstand, linear
field-particle-linear-drag-help = Luftwiderstand b: eine Kraft b v entgegen der Bewegung (langsame Bewegung in einer zähen Flüssigkeit)
field-particle-quadratic-drag = Luftwiderstand, quadratisch
field-particle-quadratic-drag-help = Luftwiderstand c: eine Kraft c v² entgegen der Bewegung (ein Ball in Luft: c = ½ ρ C_d A)
field-particle-drag-coefficient = Widerstandsbeiwert
field-particle-drag-coefficient-help = C_d: Luftwiderstand ½ ρ C_d π r² v² aus der Luftdichte der Welt und dem Radius (ein Ball: 0,47); statt des quadratischen c
field-particle-inertia = Trägheitsmoment
field-particle-inertia-help = I/(m r²): 0 ein Punkt, der sich nie dreht, 0,5 eine Vollscheibe, 1 ein dünner Ring
field-particle-spin = Drehung
field-particle-spin-help = Winkelgeschwindigkeit ω, gegen den Uhrzeigersinn positiv (eines sich drehenden Teilchens)
field-particle-angle = Winkel
field-particle-angle-help = Ausrichtung, gegen den Uhrzeigersinn: wohin der markierte Radius des sich drehenden Teilchens zeigt
field-particle-color = Farbe
field-particle-color-help = Anzeigefarbe, "#rrggbb"
field-spring-from = von
field-spring-from-help = Der Name eines Teilchens oder ein fester Punkt [x, y]
field-spring-to = nach
field-spring-to-help = Der Name eines Teilchens oder ein fester Punkt [x, y]
field-spring-stiffness = Federkonstante
field-spring-stiffness-help = k, 0 oder mehr
field-spring-natural-length = Ruhelänge
field-spring-natural-length-help = Die Länge, bei der die Feder keine Kraft ausübt
field-spring-damping = Dämpfung
field-spring-damping-help = b: Kraft −b·(Relativgeschwindigkeit entlang der Feder)
field-rod-from = von
field-rod-from-help = Der Name eines Teilchens oder ein fester Punkt [x, y]
field-rod-to = nach
field-rod-to-help = Der Name eines Teilchens oder ein fester Punkt [x, y]
field-rod-length = Länge
field-rod-length-help = Der Abstand, den die Stange zwischen ihren Enden hält
field-string-from = von
field-string-from-help = Der Name eines Teilchens oder ein fester Punkt [x, y]
field-string-to = nach
field-string-to-help = Der Name eines Teilchens oder ein fester Punkt [x, y]
field-string-length = Länge
field-string-length-help = Wie weit der Faden seine Enden höchstens auseinander lässt
field-string-restitution = Stoßzahl
field-string-restitution-help = Wenn er sich strafft: 0 (die Enden entfernen sich nicht mehr) bis 1 (sie prallen zurück)
field-ramp-from = von
field-ramp-from-help = Ein Ende der Rampe
field-ramp-to = nach
field-ramp-to-help = Das andere Ende
field-ramp-thickness = Dicke
field-ramp-thickness-help = Die Rampe ist jeder Punkt innerhalb der halben Dicke um ihre Strecke
field-ramp-restitution = Stoßzahl
field-ramp-restitution-help = 0 (kein Abprall) bis 1 (vollkommen elastisch)
field-ramp-friction = Reibung
field-ramp-friction-help = Koeffizient der Haft- und Gleitreibung
inspector-name = Name
inspector-name-hint = Eindeutig unter allen Objekten
inspector-rod-length-differs = Ihre Enden sind zu Beginn { $distance } m voneinander entfernt, nicht { $length } m: die Stange zieht sie vor dem ersten Schritt auf ihre Länge.
inspector-string-too-short = Seine Enden sind zu Beginn { $distance } m voneinander entfernt, mehr als seine { $length } m: der Faden zieht sie vor dem ersten Schritt auf seine Länge.
inspector-bounds-min-hint = Die linke untere Ecke des Kastens
inspector-bounds-max-hint = Die rechte obere Ecke des Kastens
inspector-fixed-point = fester Punkt
inspector-end-hint = Ein Teilchen oder ein fester Punkt der Welt
inspector-end-point = { $end }: Punkt
inspector-end-point-hint = Der feste Punkt, Meter

## Graphs, the status line, edits (Undo and Redo), file errors
notice-no-example = es gibt kein Beispiel '{ $name }'
notice-cannot-read-in-browser = '{ $path }' lässt sich im Browser nicht lesen
status-frame-time = Bild { $ms } ms
status-objects = { $particles } Teilchen, { $springs } Federn, { $ties } Stangen und Fäden, { $ramps } Rampen
edit-set = { $what } ändern
edit-add-graph = Graph hinzufügen
edit-remove-graph = Graph entfernen
edit-add-series = Kurve hinzufügen
edit-remove-series = Kurve entfernen
edit-set-x-axis = x-Achse ändern
edit-paste = einfügen
edit-move-group = Auswahl verschieben
edit-delete-group = Auswahl löschen
edit-set-time-scale = Zeitmaßstab ändern
edit-set-integrator = Integrator ändern
edit-set-time-step = Zeitschritt ändern
edit-edit-from-here = von hier bearbeiten
edit-move-particle = Teilchen verschieben
edit-move-ramp = Rampe verschieben
edit-move-ramp-end = Rampenende verschieben
edit-set-velocity = Geschwindigkeit ändern
edit-add-particle = Teilchen hinzufügen
edit-add-spring = Feder hinzufügen
edit-add-rod = Stange hinzufügen
edit-add-string = Faden hinzufügen
edit-add-ramp = Rampe hinzufügen
edit-rename = umbenennen
edit-delete-particle = Teilchen löschen
edit-delete-spring = Feder löschen
edit-delete-rod = Stange löschen
edit-delete-string = Faden löschen
edit-delete-ramp = Rampe löschen
graph-untitled = Diagramm { $number }
graph-figure-title = { $y } über { $x }
graph-particle = Teilchen
graph-particle-hint = Das Teilchen, dessen Größe hinzukommt
graph-quantity = Größe
graph-quantity-hint = Die Größe, die hinzukommt
graph-tension-hint = Die Kraft zeichnen, die diese Stange oder dieser Faden trägt (Zug ist positiv)
graph-marks = Extrema und Nullstellen
graph-marks-hint = Maxima, Minima und Nulldurchgänge jeder Kurve markieren, im Lauf genau bestimmt, sobald er anhält (angesteuert wie die Ereignisse der Stoppuhr; während er läuft und in sehr großen Szenen aus den Abtastwerten gelesen), und die Periode aus aufeinanderfolgenden Maxima angeben
graph-earlier-runs = frühere Läufe
graph-forget-earlier = frühere Läufe vergessen
graph-forget-earlier-hint = Die grauen Kurven sind die Läufe vor dem letzten (bis zu drei, von Start zu Start behalten); sie vergessen
graph-fit = Anpassung
graph-fit-hint = Jede Kurve nach der Methode der kleinsten Quadrate an ein Modell anpassen: seine Parameter mit ihren Standardunsicherheiten, die Kurve gestrichelt
graph-fit-none = keine
graph-fit-line = Gerade a + b x
graph-fit-parabola = Parabel a + b x + c x²
graph-fit-sine = Sinus A sin(ω x + φ) + c
graph-fit-decay = Abklingen A e^(−x/τ) + c
graph-fit-result = { $quantity }, { $model }: { $parameters } (mittlere Abweichung { $rms })
graph-reset-view = Ansicht zurücksetzen
graph-reset-view-hint = Wieder den ganzen Lauf zeigen (Strg und das Mausrad zoomen, Ziehen verschiebt)
graph-period = Periode von { $quantity }: { $period } s (Mittel aus { $cycles } { $cycles ->
    [one] Zyklus
   *[other] Zyklen
} mit { $maxima } { $maxima ->
    [one] Maximum
   *[other] Maxima
}, { $how ->
    [located] im Lauf bestimmt
   *[sampled] aus den Abtastwerten gelesen
})
graph-period-too-few = Periode von { $quantity }: noch keine ({ $count } Maxima; ein drittes zeigt, ob sie sich wiederholen)
graph-period-irregular = Periode von { $quantity }: nicht bestimmbar (ihre { $count } Maxima wiederholen sich in keinem regelmäßigen Zyklus)
graph-angle-hint = Den Winkel dieser Stange, dieses Fadens oder dieser Feder zur Senkrechten nach unten zeichnen (gegen den Uhrzeigersinn positiv)
graph-length-hint = Den Abstand der Enden dieser Stange, dieses Fadens oder dieser Feder zeichnen
graph-total-hint = Diese Größe des Systems zeichnen
graph-x-axis-now = x-Achse: { $quantity }
graph-remove-series-hint = Diese Kurve entfernen
impacts-go-to-hint = Den Lauf bei diesem Stoß zeigen
units-comes-to = es ergibt { $value }
units-empty = es ist leer
units-brackets = die Klammern passen nicht zusammen
units-ends-with-operator = es endet mit einem Rechenzeichen
units-unknown-word = „{ $word }“ ist keine Funktion, Konstante oder Einheit dieses Feldes
units-unreadable = es lässt sich nicht als Rechnung lesen
expression-too-long = ein Ausdruck aus { $length } Zeichen ist länger als jede Formel, die NewtonLab liest (höchstens { $most })
expression-too-deep = ein Ausdruck mit { $depth } Klammerebenen ist tiefer geschachtelt als jede Formel, die NewtonLab liest (höchstens { $most })
units-not-a-number = „{ $text }“ ist keine Zahl: { $reason }; schreiben Sie eine Zahl oder eine Rechnung wie 2*pi oder sqrt(2)/2
units-not-a-number-unit = „{ $text }“ ist keine Zahl: { $reason }; schreiben Sie eine Zahl oder eine Rechnung wie 2*pi oder sqrt(2)/2, mit einer Einheit wie { $units }
file-cannot-read = '{ $path }' lässt sich nicht lesen: { $error }
file-cannot-write = '{ $path }' lässt sich nicht schreiben: { $error }
file-cannot-read-file = '{ $path }' lässt sich nicht lesen
file-cannot-download = der Browser konnte '{ $path }' nicht herunterladen
file-cannot-autosave = automatisches Speichern in '{ $path }' nicht möglich: { $error }
file-cannot-encode = das Bild ließ sich nicht kodieren: { $error }
reading-full = { $value } (der volle Wert: zum Kopieren klicken)
reading-copied = { $value } in die Zwischenablage kopiert.
experiments-heading = Versuchsreihen
experiments-heading-hint = Einen Wert der Szene variieren, für jeden Wert einmal laufen lassen und auftragen, was jeder Lauf gemessen hat, mit dem erwarteten Gesetz
experiment-add = Versuchsreihe hinzufügen
experiment-add-hint = Eine Reihe für das gewählte Teilchen (oder das erste): sein Abwurfwinkel von 15° bis 75°, gemessen wird sein höchster Punkt; jedes Feld lässt sich ändern
experiment-none = Diese Versuchsreihe gibt es nicht.
experiment-title = Reihe { $number }
experiment-figure-title = { $measure } über { $vary }
experiment-remove = entfernen
experiment-remove-hint = Diese Reihe aus der Szene entfernen
experiment-vary = variiere
experiment-vary-hint = Der variierte Wert, wie ihn die Szenendatei nennt: Ball.velocity.angle, Bob.mass, world.gravity.y, simulation.time_step
experiment-from = von
experiment-from-hint = Der erste Wert
experiment-to = bis
experiment-to-hint = Der letzte Wert (erreicht, wenn die Schritte ihn erreichen)
experiment-step = Schritt
experiment-step-hint = Der Schritt zwischen den Werten
experiment-until = bis t (s)
experiment-until-hint = Wie lange jeder Lauf dauert, Sekunden simulierter Zeit
experiment-measure = Messung
experiment-measure-hint = Was an jedem Lauf gemessen wird, durch ";" getrennt: Ball.x at Ball.y crosses 0 down, t at Bob.vx crosses 0 #3, max Ball.y, min Ball.vy, period Bob.x, Ball.x at 1.5
experiment-theory = Theorie
experiment-theory-hint = Wahlweise: das Gesetz der ersten Messung, in x (oder a: der variierte Wert, ein Winkel im Bogenmaß) und den Konstanten der Szene g, m, r, v0, h, b, c (die des variierten Teilchens), L, k. v0^2*sin(2*a)/g ist die Wurfweite
experiment-run = Reihe ausführen
experiment-run-hint = Die Szene für jeden Wert einmal laufen lassen (auf allen Kernen) und die Messungen auftragen
experiment-progress = { $done } von { $total } Läufen
experiment-took = { $runs } Läufe in { $seconds } s
experiment-export-csv-hint = Die Ergebnisse als CSV: der variierte Wert, dann jede Messung (wie newtonlab sweep sie schreibt)
experiment-residuals = { $measure } − Theorie: höchstens { $worst }
experiment-residual = gemessen − Theorie
experiment-theory-curve = Theorie: { $law }
edit-add-experiment = Versuchsreihe hinzufügen
edit-change-experiment = Versuchsreihe ändern
edit-remove-experiment = Versuchsreihe entfernen
experiment-choose = wählen…
experiment-choose-hint = Den variierten Wert unter denen des gewählten Teilchens (oder des ersten) und der Welt wählen
experiment-add-measure = Messung hinzufügen…
experiment-add-measure-hint = Eine oft gebrauchte Messung hinzufügen, für das gewählte Teilchen (oder das erste) und jede Stange oder jeden Faden; im Feld anpassen
scene-clock-too-coarse = der Zeitschritt { $step } s ist zu fein für eine Uhr bei { $start } s: ein Zeitpunkt dort wird um mehr als 1e-4 eines Schritts gerundet (den Zeitschritt mindestens ein Billionstel der Startzeit wählen oder näher bei 0 beginnen)
scene-same-point = beginnt am selben Punkt wie Teilchen „{ $other }“, wo die Kraft zwischen ihnen unendlich ist: eines verschieben oder [world] eine Glättung (softening) geben
cli-every-too-fine = --every { $every } ist zu fein für Zeitpunkte bis { $until } s: die Zeilenzeiten k × every fielen zusammen (ein größeres --every wählen)
cli-state-not-saveable = der Zustand bei { $time } s lässt sich nicht als wieder ladbare Szene speichern: { $problem }
total-kinetic-energy = kinetische Energie
total-potential-energy = potentielle Energie
total-total-energy = Gesamtenergie
total-momentum-x = Impuls x
total-momentum-y = Impuls y
total-angular-momentum = Drehimpuls
cli-not-a-file = „{ $source }“ ist keine Datei (ein Verzeichnis, ein Gerät oder eine Pipe): eine Szenendatei angeben oder example:NAME
cli-file-too-large = „{ $source }“ ist { $megabytes } MB groß: eine Szenendatei darf höchstens { $most } MB groß sein
cli-same-output = { $first } und { $second } nennen beide „{ $path }“: ihre Zeilen würden sich mischen; jedem eine eigene Datei geben
scene-inside-ramp = beginnt mit seinem Mittelpunkt in der Rampe „{ $ramp }“: außerhalb der Rampe platzieren (auf ihr bleibt es liegen)
cli-too-much-work = --until { $until } bräuchte { $steps } Schritte von { $particles } beweglichen Teilchen, { $work } Teilchen-Schritte, mehr als { $most } (Minuten bis Stunden Arbeit); einen größeren time_step, ein kürzeres --until oder weniger Teilchen wählen oder --no-limit angeben
run-tie-not-held = bei t = { $time } s ließ sich Stange oder Seil „{ $tie }“ nicht auf seiner Länge halten: die Kräfte darauf sind zu stark für den Zeitschritt, die Massen seiner Enden zu ungleich, oder seine Länge verträgt sich nicht mit den anderen; einen kleineren time_step wählen oder Längen und Massen prüfen
run-pulley-reached = bei t = { $time } s hat der Körper „{ $body }“ das Rad der Rolle „{ $pulley }“ erreicht: seine Seite der Schnur ist aufgebraucht (den Lauf früher beenden oder den Körper tiefer hängen)
run-tie-too-far = bei t = { $time } s liegt Stange oder Seil „{ $tie }“ zu weit vom Ursprung für seine Länge von { $length } m: schon das Runden der Positionen seiner Enden verhindert, dass es auf ein Milliardstel seiner Länge gehalten wird; die Szene näher an den Ursprung legen oder die Verbindung länger machen
run-drag-too-strong = bei t = { $time } s bremst der Luftwiderstand Teilchen „{ $particle }“ alle { $decay } s um den Faktor e, schneller als ein Zeitschritt von { $step } s folgen kann (das Verfahren erzeugte Energie aus dem Nichts); einen time_step von höchstens diesem Wert wählen, oder dopri5
run-left-bounds = bei t = { $time } s verließ Teilchen „{ $particle }“ die Weltgrenzen mit { $speed } m/s, zu schnell, als dass der Zeitschritt seine Stöße mit den Wänden auflösen könnte; einen kleineren time_step wählen
scene-got-null = null
scene-json-duplicate-key = der Schlüssel „{ $key }“ steht zweimal in einem Objekt; einen behalten
scene-number-beyond-f64 = { $text } liegt jenseits dessen, was eine 64-Bit-Zahl fasst (etwa 2,2e-308 bis 1,8e308 dem Betrag nach, oder 0)
file-save-changes = Speichern
file-save-changes-hint = Die Änderungen speichern, dann weiter
scene-body-shape = shape muss "box" oder "polygon" sein, nicht "{ $got }"
scene-must-be-points = muss eine Liste von Punkten sein, wie [[0.0, 0.0], [0.4, 0.0], [0.2, 0.3]], nicht { $got }
scene-body-box-size = ein Quader braucht { $field } größer als 0
scene-body-not-box = { $field } gehört zu einem Quader: der Umriss eines Polygons sind seine Ecken ({ $field } weglassen)
scene-body-vertex-count = ein Polygon braucht 3 bis { $most } Ecken, nicht { $count }
scene-body-vertex-not-finite = Ecke { $k } ist kein endlicher Punkt einer Größe, die NewtonLab simuliert (höchstens 1e100)
scene-body-repeated-vertex = die Ecken { $a } und { $b } sind derselbe Punkt: eine weglassen
scene-body-collinear = die Ecken { $a }, { $b } und { $c } liegen auf einer Geraden: die mittlere weglassen
scene-body-clockwise = die Ecken laufen im Uhrzeigersinn: gegen den Uhrzeigersinn angeben (die Liste umkehren)
scene-body-concave = der Umriss ist an Ecke { $k } nicht konvex: ein Körper muss konvex sein (eine konkave Form aus mehreren Körpern bauen)
scene-body-winds = der Umriss kreuzt sich selbst (er läuft mehr als einmal herum): die Ecken der Reihe nach um den Umriss angeben
scene-body-no-mass = braucht eine Masse (kg) oder eine Dichte (kg/m²)
scene-body-mass-and-density = eine Masse oder eine Dichte angeben, nicht beides
scene-body-static-friction = static_friction { $static } muss mindestens die Gleitreibung { $kinetic } sein
scene-body-overlap = überlappt am Anfang den Körper „{ $other }“: die beiden auseinanderrücken
scene-motor = motor muss {"{"} torque = N·m {"}"} oder {"{"} spin = rad/s, max_torque = N·m {"}"} sein
scene-joint-no-body = es gibt keinen Körper „{ $name }“ (Stifte, Scharniere und Rollen halten Körper, [[body]])
scene-joint-particle = „{ $name }“ ist ein Teilchen: Stifte, Scharniere und Rollen halten Körper ([[body]]), noch keine Teilchen; Teilchen verbindet eine Stange oder ein Faden
scene-hinge-itself = ein Scharnier verbindet zwei Körper, aber a und b sind beide „{ $body }“
scene-joint-twice = hält dieselben Körper am selben Punkt wie „{ $other }“: lass eines weg
scene-joint-fixed = hält nichts Bewegliches: jeder verbundene Körper ist fest
scene-joint-anchor = { $field } liegt nicht am Gelenkpunkt at: lass es weg, dann wird es aus at bestimmt
scene-pulley-same = die Schnur einer Rolle verbindet zwei Körper, aber a und b sind beide „{ $body }“
scene-pulley-inside = der Körper „{ $body }“ ist am Rad: er muss frei unter dem Rad der Rolle hängen
scene-force-unreadable = '{ $text }' ist kein Ausdruck: aus x, y, vx, vy, t, m, q mit Zahlen, + − * / ^, sqrt, sin, cos, exp, … bilden (zum Beispiel -2*x - 0.5*x^3)
scene-force-unknown-name = nennt '{ $name }': eine Kraft darf { $names } nennen
scene-force-potential-name = nennt '{ $name }': eine potentielle Energie hängt nur vom Ort ab und darf { $names } nennen
scene-force-on-body = '{ $name }' ist ein Körper: eigene Kräfte wirken auf Teilchen
scene-force-on-nothing = es gibt kein Teilchen '{ $name }'
scene-force-not-finite = auf Teilchen '{ $particle }' ist die Kraft am Start ({ $x }, { $y }) N, keine endliche Kraft
scene-force-potential-of-motion = eine potentielle Energie gehört zu einer Kraft, die nur vom Ort abhängt, und diese Kraft nennt die Geschwindigkeit oder die Zeit: das Potential weglassen
scene-force-potential-mismatch = am Start von Teilchen '{ $particle }' ist −∇U des Potentials ({ $ux }, { $uy }) N, die Kraft aber ({ $fx }, { $fy }) N: die Energiebilanz ginge nicht auf; das Potential dieser Kraft angeben, oder keines
scene-limits = limits muss [untere, obere] in Grad sein
scene-limits-order = limits müssen endlich sein und die untere unter der oberen liegen, nicht [{ $lower }, { $upper }]
scene-limits-start = der Winkel des Gelenks am Anfang, { $angle }°, liegt außerhalb seiner limits
cli-check-body = Körper „{ $name }“: { $shape }, Fläche { $area } m², Masse { $mass } kg, Trägheitsmoment { $inertia } kg·m² um seinen Schwerpunkt, bei { $centroid } m im Umriss wie eingegeben
cli-check-pin = Stift „{ $name }“: hält den Körper „{ $body }“ bei { $at } m; sein Trägheitsmoment um den Stift ist { $inertia } kg·m²
cli-check-hinge = Scharnier „{ $name }“: verbindet den Körper „{ $b }“ mit dem Körper „{ $a }“ bei { $at } m
cli-check-pulley = Rolle „{ $name }“: eine Schnur vom Körper „{ $a }“ über ein Rad mit Radius { $radius } m und { $mass } kg bei { $at } m zum Körper „{ $b }“
cli-check-force = Kraft '{ $name }': ({ $fx }, { $fy }) N auf { $on }; ohne Potential, der Rest der Energiebilanz enthält ihre Arbeit
cli-check-force-potential = Kraft '{ $name }': ({ $fx }, { $fy }) N auf { $on }, mit ihrer potentiellen Energie
cli-check-force-everything = jedes Teilchen
cli-check-magnetic = Magnetfeld B_z = { $field } T auf { $charged } geladene Teilchen (q v × B: es lenkt sie ab und verrichtet keine Arbeit)
cli-check-joints-start = die Geschwindigkeiten der Körper am Anfang reißen ihre Gelenke auseinander: der Lauf beginnt mit den nächsten Geschwindigkeiten, die die Gelenke erlauben, { $lost } J kinetische Energie weniger
cli-check-motor-torque = , angetrieben von einem Motor mit { $torque } N·m
cli-check-motor-spin = , angetrieben von einem Motor auf { $spin } rad/s mit höchstens { $torque } N·m
cli-check-bodies-free = Körper stoßen an Wände, Rampen und einander, liegen auf ihnen auf und gleiten (zwischen zwei Körpern die kleinere Stoßzahl, das geometrische Mittel der Reibungen); Körper an Stiften und Scharnieren begegnen noch nichts; Teilchen begegnen Körper noch nicht, und Federn, Stangen und Fäden greifen noch nicht an ihnen an
edit-move-body = Körper verschieben
edit-add-body = Körper hinzufügen
edit-delete-body = Körper löschen
edit-add-pin = Stift hinzufügen
edit-delete-pin = Stift löschen
edit-add-hinge = Scharnier hinzufügen
edit-delete-hinge = Scharnier löschen
edit-add-pulley = Rolle hinzufügen
edit-delete-pulley = Rolle löschen
edit-add-force = Kraft hinzufügen
edit-delete-force = Kraft löschen
tool-box = Quader
tool-box-hint = Von Ecke zu Ecke ziehen, um einen starren Quader zu zeichnen (7)
field-body-width = Breite
field-body-width-help = Ausdehnung eines Quaders entlang seiner eigenen x-Achse
field-body-height = Höhe
field-body-height-help = Ausdehnung eines Quaders entlang seiner eigenen y-Achse
field-body-mass = Masse
field-body-mass-help = Masse, größer als 0 (oder stattdessen die Dichte angeben)
field-body-density = Dichte
field-body-density-help = Masse pro Fläche: die Fläche der Form ergibt die Masse
field-body-position = Position
field-body-position-help = Der Schwerpunkt
field-body-angle = Winkel
field-body-angle-help = Ausrichtung, gegen den Uhrzeigersinn
field-body-velocity = Geschwindigkeit
field-body-velocity-help = Die Geschwindigkeit des Schwerpunkts
field-body-spin = Drehung
field-body-spin-help = Winkelgeschwindigkeit ω, gegen den Uhrzeigersinn positiv
field-body-restitution = Stoßzahl
field-body-restitution-help = 0 (kein Abprall) bis 1 (vollkommen elastisch)
field-body-friction = Reibung
field-body-friction-help = Gleitreibungskoeffizient
field-body-fixed = fest
field-body-fixed-help = Ein fester Körper bewegt sich nie
field-body-color = Farbe
field-body-color-help = Anzeigefarbe, "#rrggbb"
status-bodies = { $bodies } Körper
tool-polygon = Polygon
tool-polygon-hint = Die Ecken eines starren konvexen Polygons anklicken; die erste erneut anklicken, um es zu schließen (8)
lesson-no-title = eine Lektion braucht einen Titel
lesson-text-too-long = der Text hat { $size } KiB; der Text einer Lektion darf höchstens { $most } KiB haben (ein Bild gehört neben die Szene, nicht hinein)
lesson-html = der Text enthält HTML (ein Tag wie <script> oder <img>), das eine Lektion nie zeigt oder ausführt: schreiben Sie Markdown und in einer Formel ein Leerzeichen nach <
lesson-bad-id = die Kennung '{ $id }' darf nur Buchstaben, Ziffern, _ oder - enthalten (eine Antwort nennt sie: ID=WERT)
lesson-repeated-id = die Kennung '{ $id }' hat schon eine frühere Frage
lesson-no-prompt = eine Frage braucht einen Fragetext
lesson-unit-misfit = die Einheit '{ $unit }' passt nicht zur Messung, die in { $si } misst
lesson-tolerance = tolerance muss größer als 0 sein, ist aber { $tolerance }
lesson-slider-range = min { $min } muss kleiner als max { $max } sein
lesson-slider-step = step muss größer als 0 und höchstens max − min sein, ist aber { $step }
lesson-slider-rule = bei { $value } verletzt die Szene eine Regel: { $why }
cli-check-lesson = Lektion '{ $title }': { $sliders } Schieberegler, { $questions } Frage(n)
cli-lesson-none = { $source } hat keine [lesson]: geben Sie eine Szenendatei mit einer Lektion an, oder eine Beispiel-Lektion (newtonlab examples)
cli-lesson-answer-malformed = --answer '{ $text }' muss ID=WERT sein, etwa { $first }="1.5 s"; die Kennungen: { $ids }
cli-lesson-unknown-id = --answer '{ $text }': die Lektion hat keine Frage mit dieser Kennung; ihre { $count } Frage(n): { $ids }
cli-lesson-answer-unreadable = --answer für '{ $id }' muss eine Größe in { $unit } sein (oder in einer anderen Einheit dieser Art): { $why }
cli-lesson-unmeasured = die Simulation kann die Frage '{ $id }' nicht beantworten: { $why }
menu-lesson = Lektion
menu-lesson-hint = Die Lektion zeigen oder verbergen: Anleitung, Schieberegler und Fragen
key-lesson = Lektion zeigen oder verbergen
edit-slide = Schieberegler der Lektion bewegen
inspector-about = Über diese Szene
lesson-sliders = Probieren Sie
lesson-sliders-reset = Setzen Sie den Lauf zurück, um diese zu ändern
lesson-questions = Fragen
lesson-answer-hint = Ihre Antwort, in { $unit }
lesson-check = Prüfen
lesson-right = Richtig
lesson-close = Knapp daneben — prüfen Sie Ihre Messung
lesson-not-yet = Noch nicht — messen Sie noch einmal
lesson-revealed = Die Simulation misst { $value }.
worksheet-no-lesson = die Szene hat keine Lektion: ein Arbeitsblatt gehört zu einer Lektion ([lesson] in der Szenendatei)
worksheet-no-font = die mitgelieferte Schrift konnte für das Arbeitsblatt nicht gelesen werden
worksheet-no-picture = das Bild der Szene hat keine Größe
worksheet-failed = das Arbeitsblatt konnte nicht geschrieben werden: { $why }
worksheet-name = Name:
worksheet-sliders = Sie dürfen ändern
worksheet-slider = { $field }: von { $min } bis { $max }{ $unit }, in Schritten von { $step }
worksheet-key-title = Lösungen: { $title }
worksheet-key-line = { $id }: { $value } { $unit } (richtig innerhalb ± { $tolerance }, knapp innerhalb ± { $close })
worksheet-key-none = { $id }: die Simulation liefert keinen Wert: { $why }
menu-worksheet = Arbeitsblatt exportieren…
menu-worksheet-hint = Die Lektion als Arbeitsblatt zum Drucken (PDF): Anleitung, ein Bild der Szene und die Fragen mit Linien für die Antworten
menu-answer-key = Arbeitsblatt mit Lösungen exportieren…
menu-answer-key-hint = Das Arbeitsblatt, danach der Wert der Simulation für jede Frage auf einer eigenen Seite (PDF)
file-title-pdf = Arbeitsblatt exportieren (PDF)
notice-worksheet-saved = Arbeitsblatt gespeichert: { $path }
menu-fields = Felder und Kräfte
menu-bodies = Starre Körper
menu-lessons = Lektionen
