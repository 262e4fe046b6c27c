# NewtonLab's messages in English: the reference every other language follows.
# A message is `id = text`; `{ $name }` is an argument the app fills in.

## Menus
menu-file = File
menu-file-hint = New, open, save, share
menu-new = New
menu-new-hint = An empty scene
menu-open = Open…
menu-open-hint = Open a scene file
menu-save = Save
menu-save-hint = Save the scene
menu-save-canvas = Save the canvas as PNG…
menu-save-canvas-hint = A picture of the canvas as it is on screen, at twice the screen's resolution to print (in the browser, as on screen)
menu-save-as = Save As…
menu-save-as-hint = Save the scene under another name
menu-copy-link = Copy link to this scene
menu-copy-link-hint = A link that opens this scene: in the address bar and the clipboard
menu-link-copied = A link to this scene is in the address bar and on the clipboard.
menu-edit = Edit
menu-edit-hint = Undo, redo, delete
menu-undo = Undo
menu-undo-what = Undo { $what }
menu-undo-hint = Undo the last change
menu-redo = Redo
menu-redo-what = Redo { $what }
menu-redo-hint = Redo what was undone
menu-delete = Delete
menu-delete-hint = Remove the selected object
menu-cut = Cut
menu-cut-hint = Copy the selected object, then remove it
menu-copy = Copy
menu-copy-hint = Copy the selected object (a spring, rod or string with the particles it ties) as scene-file text
menu-paste = Paste
menu-paste-hint = Add what was copied beside where it was, renamed where names are taken (Ctrl+V pastes scene-file text from other programs too)
menu-duplicate = Duplicate
menu-duplicate-hint = Copy the selected object and paste it beside itself
menu-examples = Examples
menu-examples-hint = Open a built-in scene (the paper's experiments and more)
menu-view = View
menu-view-hint = Framing, panels, projector mode, language
menu-fit = Fit
menu-fit-hint = Fit the scene and the recent paths in view
menu-inspector = Inspector
menu-inspector-hint = Show or hide the inspector
menu-graphs = Graphs
menu-graphs-hint = Show or hide the graphs and readouts
menu-projector = Projector mode
menu-projector-hint = The canvas alone with large text, for a class
menu-follow = Follow
menu-follow-hint = Keep a particle, or all of them, in view while playing
menu-language = Language
menu-language-hint = The language of the app; it changes at once
menu-text-size = Text size
menu-text-size-hint = Larger text and controls; kept for the next time
menu-high-contrast = High contrast
menu-high-contrast-hint = Black on white with strong outlines; kept for the next time
menu-measure = Measure
menu-measure-hint = Tape measure, field probe, field view
menu-no-field = No field view
menu-electric-field = Electric field view
menu-gravitational-field = Gravitational field view
menu-field-hint = Arrows of the particles' field across the canvas, stronger where darker
menu-stopwatch = Stopwatch
menu-stopwatch-hint = Simulated time between two events: by hand, an impact, a particle crossing the tape
menu-clear-measurements = Clear measurements
menu-clear-measurements-hint = Take away the tape, the probe and the protractor
menu-help = Help
menu-keys = Keys
menu-keys-hint = Every shortcut, and how to use the canvas from the keyboard
menu-getting-started = Getting started
menu-getting-started-hint = Three short tasks: place and run, measure, graph
start-title = Getting started
start-intro = Three short tasks, a minute each, to find your way. Help › Getting started opens this page again; F1 lists every key.
start-place = Place and run
start-place-1 = File › New: an empty scene, with gravity.
start-place-2 = Press 2 (Particle) and click the canvas: a ball of 1 kg.
start-place-3 = In the Inspector on the left, type a velocity x of 3 (units work too: 30 km/h).
start-place-4 = Press Space to play and again to pause; R resets to the scene as you built it.
start-measure = Measure
start-measure-1 = Examples › Pendulum on a rod, released at 60°; Space, and after a swing or two Space again.
start-measure-2 = Under the graph, tick extremes and zeros: it reads the period, 3.044625 s, as theory gives it.
start-measure-3 = turn » in the time bar shows the bob at its next turning point, exactly.
start-graph = Graph
start-graph-1 = Add a graph, choose a particle and a quantity, then Add.
start-graph-2 = Choose vx and Use as x axis: a phase plot. A series added later still has the whole run.
start-graph-3 = Export CSV… saves every sample for a spreadsheet.

## Tool bar
toolbar-play = Play
toolbar-pause = Pause
toolbar-play-hint = Run or pause the simulation (Space)
toolbar-step = Step
toolbar-step-hint = Advance by one time step (.)
toolbar-reset = Reset
toolbar-reset-hint = Back to the scene as last edited (R)
toolbar-time-scale-hint = Time scale: simulated seconds per real second (0.01× to 100×)
toolbar-integrator-hint = How the motion is integrated in time
toolbar-time-step-hint = Time step, seconds (dopri5: the largest step)
toolbar-fit-hint = Fit the scene and the recent paths in view (F)
toolbar-velocity = velocity
toolbar-velocity-hint = Velocity arrows (tip: where the particle will be in 0.5 s)
toolbar-acceleration = acceleration
toolbar-acceleration-hint = Acceleration arrows
toolbar-force = force
toolbar-force-hint = Net force arrows (length grows with the logarithm of the force)
toolbar-trails = trails
toolbar-trails-hint = Recent paths of the particles
toolbar-names = names
toolbar-names-hint = Object names
follow-nothing = nothing
follow-nothing-hint = A still camera
follow-all = all particles
follow-all-hint = Keep every particle in view
follow-particle-hint = Keep this particle at the centre

## Tools
tool-select = Select
tool-particle = Particle
tool-spring = Spring
tool-rod = Rod
tool-string = String
tool-ramp = Ramp

## Status line
status-behind = running at { $ratio }× of the requested speed ({ $real }× real time)
status-real-time = { $real }× real time
status-paused = paused
status-editing = editing
status-stopped = stopped: { $failure }; showing the last good state

## Keys (F1)
keys-title = Keys
keys-everywhere = Everywhere (except while typing in a field)
keys-canvas = On the canvas
keys-controls = Tab and Shift+Tab move between the controls; Enter or Space presses a button; the menus open with a click or, once focused, with Enter.
key-new = New scene
key-open = Open a scene file
key-save = Save
key-save-as = Save as
key-undo = Undo
key-redo = Redo
key-delete = Delete the selected object
key-duplicate = Duplicate the selected object
key-play-pause = Play or pause
key-step = One step forward
key-step-back = One step back in the run
key-next-turn = Next turning point of the selected particle
key-previous-turn = Previous turning point of the selected particle
key-reset = Reset to the scene as built
key-fit = Fit the view to the scene
key-stopwatch = Stopwatch
key-inspector = Show or hide the inspector
key-graphs = Show or hide the graphs
key-projector = Projector mode
key-help = This list of keys
key-next-region = The focus to the next region: menu, tool bar, canvas, inspector, graphs, time bar
key-previous-region = The focus to the previous region
canvas-key-focus = Give the canvas the keyboard
canvas-launch = { $speed } at { $angle }°
canvas-key-cycle = Select the next / previous object
canvas-key-move = Move the selected particle or ramp one grid step
canvas-key-fine = Move it a tenth of a grid step
canvas-key-enter = Add the current tool's object at the view's centre (a spring, rod or string from the selected particle)
canvas-key-escape = Give the keyboard back; Tab then moves to the next control
canvas-key-instrument-enter = With the tape (M) or the protractor (A): lay it from the selected particle to the next ones, or at the view's centre
canvas-key-instrument-tab = With the tape or the protractor: pick the end or point the arrow keys move
canvas-key-instrument-move = With the probe, tape or protractor: move it (its chosen point) a tenth of a grid step; Shift a hundredth
canvas-key-add = Add an object to the selection, or take it out
canvas-key-box = Select what lies in a box drawn from empty space

## Readouts and graphs
readout-heading = Energy and momentum
readout-failed = The run failed: the values of its last good sample.
readout-potential = potential (J)
readout-potential-field = potential: height, m g h (J)
readout-potential-springs = potential: springs (J)
readout-potential-gravitation = potential: gravitation (J)
readout-potential-electrostatic = potential: electrostatic (J)
readout-potential-own = potential: your forces (J)
readout-press-play = before Play
readout-at = At t = { $time }
readout-kinetic = kinetic (J)
readout-total = total (J)
readout-total-at-play = total at Play (J)
readout-damping = taken by damping (J)
readout-friction = taken by friction (J)
readout-impacts = taken by impacts (J)
readout-drag = taken by air resistance (J)
readout-motors = given by motors (J)
readout-ties = work of rods and strings (J)
readout-error = numerical error
readout-momentum = momentum (kg·m/s)
bar-kinetic = kinetic
bar-damping = damping took
bar-friction = friction took
bar-impacts = impacts took
bar-drag = air resistance took
bar-motors = motors gave
bar-total-at-play = total at Play
bars-title = Energy bars
bars-hint = Each kind of energy to one scale; the numbers are in the table above
impacts-title = Impacts ({ $count })
impacts-none = No impacts yet.
impacts-time = t (s)
impacts-particle = particle
impacts-hit = hit
impacts-impulse = impulse (N·s)
impacts-lost = lost (J)
impacts-a-ramp = a ramp
impacts-wall = wall
graph-add = Add a graph
graph-add-hint = A new graph of quantities against time
graph-remove = Remove graph
graph-remove-hint = Remove this graph (its data stays recorded)
graph-add-series = Add
graph-add-series-hint = Plot this quantity
graph-x-axis = Use as x axis
graph-x-axis-hint = Plot everything against this quantity (a phase plot)
graph-use-time = use time
graph-use-time-hint = Plot against time again
graph-export-csv = Export CSV…
graph-export-csv-hint = Save every recorded sample of this graph's quantities as a CSV file
graph-save-png = Save PNG…
graph-save-png-hint = Save this graph as a figure to print: 1200 × 800 pixels, with its title, axes, numbers, units and legend
graph-save-svg = Save SVG…
graph-save-svg-hint = Save this graph as a figure to print, as SVG: it scales to any size
graph-press-play = Press Play: the graph fills from the start of the run.

## Announcements for screen readers
announce-impact = At { $time } s, { $particle } hit { $other }.{ $more ->
    [0] {""}
    [one] {" "}And 1 more impact since the last message.
   *[other] {" "}And { $more } more impacts since the last message.
}
announce-wall = the wall
announce-stretch = At { $time } s, spring { $spring } is at full stretch, { $length } m.

## Instruments, tools, the timeline, the stopwatch, files, the inspector, links
instrument-tape = Tape measure
instrument-probe = Field probe
instrument-protractor = Protractor
instrument-tape-hint = Drag between two points to measure the distance and direction; an end on a particle follows it (M)
instrument-probe-hint = Click a point to read the gravitational and electric field and potential there; arrow keys move it (P)
instrument-protractor-hint = Drag from the vertex along the first arm, then drag again for the second: the angle between them; ends on particles follow them (A)
instrument-probe-at = at { $position } m
instrument-probe-vector = { $vector } { $unit }, size { $size } { $unit }
instrument-probe-gravitational-potential = gravitational potential { $value } J/kg
instrument-probe-electric-potential = electric potential { $value } V
tool-select-hint = Select and move objects; drag a velocity arrow's tip to set the velocity; drag empty space to pan (1)
tool-particle-hint = Click the canvas to place a particle (2)
tool-spring-hint = Drag from a particle to another particle, or to empty space for a fixed point (3)
tool-rod-hint = A rigid rod: drag from a particle to another particle, or to empty space for a fixed point (5)
tool-string-hint = A string (slack when shorter): drag from a particle to another particle, or to empty space for a fixed point (6)
tool-ramp-hint = Drag to draw a ramp (4)
stopwatch-by-hand = by hand
stopwatch-gate = crossing the tape
stopwatch-on-play = pressing Play
stopwatch-impact = an impact
stopwatch-event = an event
notice-invalid-values = Not running: some typed values are invalid (shown in red in the inspector). Correct them first:
    { $reasons }
notice-nothing-to-export = Nothing to export yet: press Play first.
notice-paste-no-scene = Nothing pasted: the clipboard holds no scene-file text ({ $reason })
notice-exported = Exported { $rows } samples to { $path }.
notice-settings-not-kept = The settings could not be kept: { $reason }
failure-reset = Reset the scene
status-physics-time = physics { $ms } ms per frame
status-physics-time-hint = Computing time spent on the simulation in each frame
inspector-title = Inspector
timeline-step-back = Step back
timeline-before-play = The time machine: press Play, then step back or go to any moment of the run
timeline-step-back-hint = One time step back in the run (,)
timeline-slider-hint = Drag to any moment of the run: it is shown exactly as it was
timeline-time = t = { $now } s of { $last } s
timeline-to-end = To the end
timeline-to-end-hint = Back to where the run is
timeline-previous-turn = « turn
timeline-next-turn = turn »
timeline-turn-hint = The selected particle's previous or next turning point ([ and ]): where its velocity's x or y passes 0, located exactly
timeline-previous-impact = « impact
timeline-next-impact = impact »
timeline-impact-hint = The previous or next impact of the run, at its located instant
timeline-go-to = go to
timeline-go-to-hint = Type an instant of the run (1.5, 1500 ms) and press Enter: it is shown exactly
timeline-no-turn = No turning point there: select a particle, and go where its velocity passes through 0 in the run.
timeline-no-impact = No impact there in the run.
timeline-edit-from-here = Edit from here
timeline-edit-from-here-hint = Make this moment the scene's start (positions, velocities and time), to change something and play a new future; undoable
stopwatch-title = Stopwatch
stopwatch-stopped = stopped
stopwatch-armed = waiting to start
stopwatch-running = running
stopwatch-stop = Stop
stopwatch-start = Start
stopwatch-reset = Reset stopwatch
stopwatch-start-on = start on
stopwatch-stop-on = stop on
stopwatch-period-at-gate = period at the gate
stopwatch-period-at-gate-hint = Start on the 1st crossing of the tape, stop on the 3rd: a full period of a pendulum swinging through a gate at its pivot
stopwatch-between-impacts = between impacts
stopwatch-between-impacts-hint = Start on the 1st impact, stop on the 2nd: a bounce's flight
stopwatch-nth = no.
stopwatch-nth-hint = Which occurrence, counted from Start: a full period of a pendulum is the 1st and the 3rd crossing of its vertical
stopwatch-event-label = event
stopwatch-event-hint = QUANTITY crosses VALUE, optionally up or down: rod.angle crosses 0 down, bob.vx crosses 0
stopwatch-lap-mode = laps
stopwatch-lap-mode-hint = Keep going: every stop is a lap, until Stop is pressed; the laps and their mean are listed
stopwatch-mean = mean { $mean } s of { $laps } laps
stopwatch-note = Simulated time. Every instant is located inside the step: impacts, the gate (a particle's centre crossing the tape) and events to a microsecond or better.
graph-ask-hint = Adds a question to the lesson whose answer is this period (the simulation checks the students' answers against it)
graph-ask-prompt = What is the period of { $quantity }?
stopwatch-ask = Ask about this
stopwatch-ask-hint = Adds a question to the lesson whose answer is this measurement: the time from Play to the event (the simulation checks the students' answers against it)
stopwatch-ask-prompt = How long after Play does this happen: { $event }?
stopwatch-asked = Question { $id } was added to the lesson; edit its prompt and tolerance in the scene file.
edit-ask = add a question to the lesson
lesson-untitled = Lesson
notice-picture-saved = Saved the picture to { $path }.
file-ok = OK
file-ok-hint = Close this message (Enter)
file-changed-title = Changed on disk
file-changed-body = “{ $path }” has changed on disk since it was opened. Overwrite it?
file-overwrite = Overwrite
file-overwrite-hint = Replace the file on disk with this scene
file-cancel = Cancel
file-keep-hint = Keep the file on disk; save under another name instead
file-recover-title = Recover unsaved work
file-recover-body = NewtonLab closed last time with changes that were not saved. Recover them?
file-recover-body-path = NewtonLab closed last time with changes to “{ $path }” that were not saved. Recover them?
file-recover = Recover
file-recover-hint = Open the unsaved work
file-discard = Discard
file-discard-hint = Throw the unsaved work away
file-unsaved-title = Unsaved changes
file-unsaved-body = “{ $title }” has changes that are not saved. Save them first?
file-discard-changes = Discard changes
file-discard-changes-hint = Lose the unsaved changes
file-keep-editing-hint = Keep editing
file-verb-open = Open
file-verb-save = Save
file-verb-export = Export
file-title-open = Open a scene
file-title-save = Save the scene
file-title-csv = Export the graph as CSV
file-title-png = Save the picture as PNG
file-title-svg = Save the figure as SVG
file-folder = folder
file-folder-hint = The folder
file-parent = .. (parent folder)
file-parent-hint = The parent folder
file-name = file name
file-name-hint = The file's name ({ $extensions })
file-submit-hint = { $verb } this file (Enter)
file-close-hint = Close without doing anything
inspector-use-cartesian = use x, y
inspector-use-polar = use polar
inspector-switch-hint = Show this vector in the other form (the value is kept)
inspector-running = Running: Reset (R) to edit the scene.
inspector-selected = Selected
inspector-selected-at-start = Selected: as the scene starts
inspector-delete = Delete
inspector-delete-hint = Remove the selected object (Delete)
inspector-world = World
inspector-simulation = Simulation
inspector-live = Live: { $name }
inspector-tension = tension
inspector-tension-hint = The force it carries: pulling is positive; 0 when slack
inspector-work-done = work done
inspector-no-work = 0 J (a constraint does no work)
inspector-live-position = position
inspector-live-velocity = velocity
inspector-live-acceleration = acceleration
inspector-live-speed = speed
inspector-live-kinetic-energy = kinetic energy
inspector-live-momentum = momentum
inspector-live-spin = spin
inspector-live-angle = angle
inspector-live-rotational = of which rotational
inspector-live-angular-momentum = angular momentum
inspector-pair-forces-direct = direct (every pair, exact)
inspector-pair-forces-tree = tree (Barnes–Hut, for thousands)
inspector-arithmetic-hint = Arithmetic and units are converted: 2*pi, sqrt(2)/2, 30 km/h, 5 cm, 250 g
inspector-polar-angle = angle
inspector-polar-angle-hint = degrees, counter-clockwise from +x
inspector-nothing-selected = Nothing selected: click an object on the canvas.
inspector-ramp-angle = slope
inspector-ramp-angle-hint = The direction from its end "from" to its end "to", degrees counter-clockwise from +x (−30 falls to the right); typing it turns the ramp about "from"
inspector-ramp-length = length
inspector-ramp-length-hint = The distance between its ends; typing it moves "to" along the slope
inspector-on-ramp = on ramp
inspector-on-ramp-hint = The ramp to put this particle on
inspector-put-on-ramp = Put on it
inspector-put-on-ramp-hint = Move this particle so it touches the ramp's upper face, at the distance below from its end "from"
inspector-along-ramp = along it
inspector-along-ramp-hint = How far along the ramp from its end "from" the particle touches it; typing it puts the particle there
inspector-inertia-presets = turns as
inspector-inertia-point = a point
inspector-inertia-point-hint = Inertia 0: never turns, feels no friction at impacts
inspector-inertia-disc = a solid disc
inspector-inertia-disc-hint = Inertia 0.5: I = ½ m r²; rolls down a slope at ⅔ g sin θ
inspector-inertia-ring = a ring
inspector-inertia-ring-hint = Inertia 1: I = m r²; rolls down a slope at ½ g sin θ
link-too-long = This link is too long to be a NewtonLab scene ({ $length } characters; the limit is { $limit }).
link-no-example = This link names a built-in scene that does not exist: '{ $name }'.
link-not-base64 = This link is damaged: its scene is not valid base64 (was it cut short or edited?).
link-too-large = This link's scene is larger than { $megabytes } MB once unpacked; it was not opened.
link-not-unpacked = This link is damaged: its scene could not be unpacked (was it cut short or edited?).
link-not-text = This link is damaged: its scene is not text.
menu-share-link = Share link…
menu-share-link-hint = A link that opens this scene, its lesson included, in the browser build: to copy into an e-mail or a class page
menu-open-link = Open link…
menu-open-link-hint = Open the scene of a NewtonLab link pasted here
link-share-title = Share link
link-open-title = Open link
link-address = Address of the browser build your class opens:
link-address-hint = Where scripts/build-web.sh's folder is served (a school server, GitHub Pages); the scene travels in the link itself, never to a server.
link-length = { $length } characters in all
link-copy = Copy link
link-copied = The link to this scene is on the clipboard.
link-paste = Paste a link to a NewtonLab scene:
link-open = Open
link-untitled = Linked scene
link-not-newtonlab = This is not a link to a NewtonLab scene: it carries no #scene= or #example= part.
link-scene-too-large = This scene is too large for a link ({ $length } characters; the limit is { $limit }): save it as a file instead.

## The scene checker (the physics crate): problems in a scene file or a typed value
scene-the-scene = scene
scene-named = { $kind ->
        [particle] particle
        [spring] spring
        [rod] rod
        [string] string
        [ramp] ramp
        [body] body
        [pin] pin
        [hinge] hinge
        [pulley] pulley
        [force] force
        [series] series
        [slider] slider
        [question] question
       *[graph] graph
    } '{ $name }'
scene-numbered = { $kind ->
        [particle] particle
        [spring] spring
        [rod] rod
        [string] string
        [ramp] ramp
        [body] body
        [pin] pin
        [hinge] hinge
        [pulley] pulley
        [force] force
        [series] series
        [slider] slider
        [question] question
       *[graph] graph
    } #{ $number }
scene-not-finite = { $field } must be a finite number, got { $value }
scene-not-positive = { $field } must be greater than 0, got { $value }
scene-negative = { $field } must be 0 or more, got { $value }
scene-not-fraction = { $field } must be between 0 and 1, got { $value }
scene-too-large = { $field } { $value } is too large to simulate reliably: numbers in a scene are 0 or between 1e-100 and 1e100 in size, so that forces and energies stay within the range of f64
scene-too-small = { $field } { $value } is too small to simulate reliably: numbers in a scene are 0 or between 1e-100 and 1e100 in size, so that forces and energies stay within the range of f64
scene-vector-not-finite = { $field } must have finite components
scene-bounds-order = bounds: min must be below and left of max, got min [{ $a }, { $b }] and max [{ $c }, { $d }]
scene-name-empty = name must not be empty
scene-name-taken = the name '{ $name }' is already used by { $earlier }; names must be unique
scene-drag-too-strong = linear drag { $a } kg/s on { $b } kg slows the particle by e every { $c } s, faster than a time step of { $d } s can follow (the method would make energy from nothing): take a time step of at most { $c } s, or dopri5
scene-drag-twice = both a quadratic air resistance c ({ $a } kg/m) and a drag coefficient ({ $b }): give one of the two (the coefficient gives c = ½ ρ C_d π r²)
scene-outside-bounds = position [{ $a }, { $b }] puts the particle (radius { $c }) outside the world bounds
scene-ends-fixed = { $kind ->
        [spring] a spring
        [rod] a rod
       *[string] a string
    } needs a moving particle at one end at least; both ends are fixed
scene-no-particle = { $field }: there is no particle named '{ $name }'
scene-ends-points = { $kind ->
        [spring] a spring
        [rod] a rod
       *[string] a string
    } needs a particle at one end at least; both ends are fixed points
scene-same-particle = both ends are the particle '{ $name }'; { $kind ->
        [spring] a spring
        [rod] a rod
       *[string] a string
    } joins two different things
scene-graph-no-particle = { $field }: '{ $text }' names no particle; there is no particle '{ $name }'
scene-graph-no-tie = { $field }: '{ $text }' names no rod or string; there is none named '{ $name }'
scene-graph-no-link = { $field }: '{ $text }' names no rod, string or spring; there is none named '{ $name }'
scene-graph-time-on-y = y: time goes on the x axis (x = "t")
scene-follow-unknown = follow: there is no particle '{ $name }'; follow a particle's name, or "all"
scene-trigger-unknown = must be one of { $words }, got '{ $got }'
scene-instrument-ends = takes { $least } to { $most } ends, each a point [x, y] or a particle's name; got { $got }
scene-count-not-whole = must be a whole number from 1 (which occurrence), got { $got }
scene-instrument-no-particle = { $field }: there is no particle named '{ $name }' for an end to follow
scene-stopwatch-stop-on-play = stop: Play can start the stopwatch, not stop it
scene-stopwatch-gate-no-tape = { $field }: the light gate is the tape measure's segment; lay a tape in [instruments]
scene-stopwatch-no-event = event: a stopwatch started or stopped by an event needs the event (bob.x crosses 0 up)
scene-stopwatch-count = { $field } must be a whole number from 1
scene-quantity-of-particle = '{ $text }': a particle's quantity is one of { $keys }; a rod's, string's or spring's is angle or length, and a rod's or string's also tension
scene-not-a-quantity = '{ $text }' is not a quantity: write t, NAME.x (or .y, .vx, .vy, .speed, .ax, .ay, .kinetic_energy; turning: .angle, .spin), ROD.angle (or .length, .tension), or one of { $keys }
quantity-no-particle = '{ $text }': there is no particle named '{ $name }' (the particles: { $names })
quantity-no-link = '{ $text }': there is no rod, string or spring named '{ $name }' (they are: { $names })
quantity-no-joint = '{ $text }': there is no pin or hinge named '{ $name }' (they are: { $names })
quantity-no-pulley = '{ $text }': there is no pulley named '{ $name }' (they are: { $names })
quantity-spring-tension = '{ $text }': '{ $name }' is a spring; its angle and length can be read, a tension only of rods and strings
event-malformed = '{ $text }' is not an event: write QUANTITY crosses VALUE, optionally followed by up or down (Ball.y crosses 0 down)
event-value = '{ $text }': '{ $value }' is not a finite number to cross
setting-object = '{ $text }' names no object of the scene: write OBJECT.key (Ball.mass, Ball.velocity.angle), world.key or simulation.key
setting-key = '{ $text }': no number of that name there (the keys are the scene file's: mass, velocity, gravity, time_step…)
setting-part = '{ $text }': a vector is varied by one part, .x, .y, .magnitude or .angle (degrees), and a number by none
vary-malformed = '{ $text }' is not a range: write FIELD=FROM:TO:STEP (Ball.velocity.angle=10:80:5)
series-too-many-runs = { $runs } runs, more than { $most }: choose coarser steps or fewer values
series-too-many-steps = a run to { $until } s would take { $steps } steps, more than { $most }: choose a larger time step or a shorter run
series-too-much-work = its { $runs } runs would take { $work } particle-steps in all, more than { $most } (hours of work): choose fewer values, a larger time step or a shorter run
vary-too-many = '{ $text }' has { $count } values, more than a million: choose a larger step
vary-empty = '{ $text }' has no values: the step must not be 0 and must lead from FROM towards TO
measure-malformed = '{ $text }' is not a measure: write QUANTITY at EVENT [#N], t at EVENT, max QUANTITY, min QUANTITY, period QUANTITY or QUANTITY at T
measure-instant = the instant { $instant } s is outside the run, { $from } s to { $until } s
measure-no-period = fewer than three maxima ({ $count }) by { $until } s: no period (two cycles at least are compared)
measure-irregular-period = its { $count } maxima by { $until } s repeat at no regular cycle: no period can be told
measure-no-event = '{ $event }' happened { $count } times by { $until } s, not { $nth }
measure-none = nothing measured by { $until } s
theory-unreadable = '{ $text }' is not an expression: write arithmetic of x (the varied value) and the scene's constants, as v0^2*sin(2*a)/g
theory-unknown-name = a theory may name { $names }; not '{ $name }'
scene-series-until = until must be a number after the scene's start, got { $until }
sweep-every-run-failed = every run of the series failed (each run's reason is above)
sweep-run-failed = run { $run }: { $why }
sweep-no-measure = run { $run }: '{ $measure }': { $why }
scene-unsatisfiable = length { $length } m cannot be kept together with the other rods and strings joined to its ends (the nearest arrangement misses it by { $miss } m); change a length or an end
scene-at-line-column = line { $line }, column { $column }
scene-at-line = line { $line }
scene-problems-found = { $source }: { $count ->
        [1] 1 problem
       *[other] { $count } problems
    } found:
scene-got-bool = true or false
scene-got-number = a number
scene-got-text = text
scene-got-list = a list
scene-got-table = a table
scene-got-date = a date
scene-bad-toml = this is not valid TOML: { $error }
scene-bad-json = this is not valid JSON: { $error }
scene-not-a-table = { $label } must be a table, got { $got }
scene-keys-here = the keys here are { $keys }
scene-did-you-mean = did you mean '{ $key }'?
scene-unknown-key = { $label }: unknown key '{ $key }'; { $hint }
scene-required = { $label }: { $key } is required
scene-the-whole = the scene
scene-version-unsupported = scene: version { $version } is not supported; this NewtonLab reads version { $supported }
scene-version-required = scene: version is required; write `version = 1` at the top of the file
scene-not-a-list = scene: '{ $key }' must be a list of [[{ $key }]] tables, got { $got }
scene-must-be-finite = must be a finite number, got { $got }
scene-must-be-number = must be a number, got { $got }
scene-must-be-bool = must be true or false, got { $got }
scene-must-be-text = must be text in quotes, got { $got }
scene-must-be-quantities = must be a list of quantities in quotes, like ["A.x", "total_energy"], got { $got }
scene-vector-length = must be { $cartesian } or { $polar }, got a list of { $count } numbers
scene-vector-extra = must be { $cartesian } or { $polar }; '{ $key }' is not a part of a vector
scene-vector-polar = must be { $cartesian } or { $polar }; a polar vector needs both magnitude and angle
scene-vector-got = must be { $cartesian } or { $polar }, got { $got }
scene-bounds-got = must be { $form }, got { $got }
scene-bounds-extra = must be { $form }; '{ $key }' is not a part of bounds
scene-bounds-both = must be { $form }; both min and max are needed
scene-endpoint-point = must be a particle's name or a point; as a point it { $reason }
scene-endpoint-got = must be a particle's name or a point [x, y], got { $got }
scene-not-integrator = '{ $name }' is not an integrator; choose one of { $names }
scene-not-pair-forces = '{ $name }' is not a way to sum pair forces; choose direct or tree
scene-not-colour = must be a colour like "#d94f4f", got "{ $text }"

## The command line
run-non-finite = at t = { $time } s particle '{ $particle }' reached a non-finite position or velocity (two bodies came too close, or the time step is too large for the forces)
run-value-not-finite = at t = { $time } s { $quantity } is { $value }, not a number a row can hold: two bodies are so close that the force between them overflows
run-step-too-small = at t = { $time } s the adaptive integrator needed a step too small to make progress with tolerance { $tolerance }; loosen the tolerance or check for bodies passing through each other
run-too-many-steps = at t = { $time } s reaching { $target } s took more than { $limit } adaptive steps (the time step of { $step } s is far too long for this scene's motion); choose a smaller time_step
cli-no-window = the app could not open a window: { $error }
    (the headless commands work without one: see `newtonlab --help`)
cli-check-ok = { $source }: ok ({ $particles } particles, { $springs } springs, { $ramps } ramps, integrator { $integrator }, time step { $step } s)
cli-check-tree = note: gravitation is summed with the Barnes–Hut tree (opening angle { $angle })
cli-check-tree-and-charges = note: gravitation is summed with the Barnes–Hut tree (opening angle { $angle }); Coulomb forces between its { $charged } charged particle(s) are summed directly, pair by pair
cli-until-not-finite = --until must be a finite number of seconds; got { $until }
cli-every-invalid = --every must be a finite number of seconds greater than 0; got { $every }
cli-event-invalid = --events: { $reason }
cli-column-invalid = --column: { $reason }
cli-until-negative = --until must be 0 or more seconds; got { $until }
cli-until-before-start = --until { $until } is before the scene's start_time { $start } s; a run goes forward from its start
cli-too-many-rows = --until { $until } with --every { $every } would write { $rows } rows of { $columns } numbers, more than { $most } numbers; choose a larger --every, or give --no-limit
cli-too-many-steps = --until { $until } at a time step of { $step } s would take { $steps } steps, more than { $most }; choose a larger time_step or a shorter --until, or give --no-limit
cli-cannot-create = cannot create the output file '{ $path }': { $error }
cli-cannot-write-csv = cannot write the CSV: { $error }
cli-cannot-save-state = cannot write the state to '{ $path }': { $error }
cli-sampling-note = note: --every { $every } s is not a whole number of time steps ({ $step } s): each sample shortens a step to land on it, so this run integrates with a smaller effective step than the scene's and its numbers differ slightly from a run sampled at a multiple of { $step } s
cli-cannot-create-log = cannot create the impact log '{ $path }': { $error }
cli-no-example = there is no built-in scene '{ $name }'; the examples are: { $names }
cli-cannot-read = cannot read the scene file '{ $source }': { $error }

## The inspector's fields (English: the field table's words, physics::fields; the file's keys stay as they are)
field-world-gravity = gravity
field-world-gravity-help = The uniform field
field-world-gravitation = gravitation between particles
field-world-gravitation-help = Newton's inverse-square attraction between every pair
field-world-gravitational-constant = G
field-world-gravitational-constant-help = The gravitational constant (the paper's value)
field-world-electrostatics = electrostatics
field-world-electrostatics-help = Coulomb's law between charged particles
field-world-coulomb-constant = k
field-world-coulomb-constant-help = The Coulomb constant
field-world-softening = softening
field-world-softening-help = Plummer softening ε of gravitation and Coulomb: force ∝ r/(r² + ε²)^(3/2), finite in close passes
field-world-air-density = air density
field-world-air-density-help = ρ, what a particle's drag coefficient pushes against: ½ ρ C_d π r² v² (air at 20 °C: 1.2)
field-world-magnetic-field = magnetic field
field-world-magnetic-field-help = B_z, out of the screen positive: a force q v × B on every moving charged particle
field-world-collisions = collisions between particles
field-world-collisions-help = Particles strike and rest on each other; false: they pass through each other (ramps and bounds still stop them)
field-world-restitution = restitution
field-world-restitution-help = Particle–particle impacts: 0 (sticky) to 1 (elastic)
field-world-friction = friction between particles
field-world-friction-help = μ between turning particles at impacts: their contact points grip within μ times the normal impulse
field-world-bounds = bounds
field-world-bounds-help = A reflecting box around the world
field-simulation-integrator = integrator
field-simulation-integrator-help = How the motion is integrated in time: euler, semi-implicit-euler, verlet, rk4, pefrl, dopri5
field-simulation-time-step = time step
field-simulation-time-step-help = The step (dopri5: the largest step)
field-simulation-tolerance = tolerance
field-simulation-tolerance-help = dopri5 only: error allowed per step, relative and absolute
field-simulation-time-scale = time scale
field-simulation-time-scale-help = Simulated seconds per real second when playing in the app
field-simulation-pair-forces = pair forces
field-simulation-pair-forces-help = How gravitation is summed: direct (every pair, exact) or tree (Barnes–Hut, for thousands of bodies)
field-simulation-opening-angle = opening angle
field-simulation-opening-angle-help = Tree only: a group of size s at distance d acts as one body when s/d is below this
field-simulation-start-time = start time
field-simulation-start-time-help = The instant the scene's state describes (a saved state keeps its time)
field-particle-mass = mass
field-particle-mass-help = Mass, greater than 0
field-particle-radius = radius
field-particle-radius-help = Radius, greater than 0
field-particle-charge = charge
field-particle-charge-help = Electric charge
field-particle-position = position
field-particle-position-help = Position
field-particle-velocity = velocity
field-particle-velocity-help = Velocity
field-particle-acceleration = acceleration
field-particle-acceleration-help = A constant applied acceleration on top of all forces
field-particle-fixed = fixed
field-particle-fixed-help = A fixed particle never moves; it still attracts, repels and is hit
field-particle-linear-drag = air resistance, linear
field-particle-linear-drag-help = Air resistance b: a force of b v against the motion (slow motion in a thick fluid)
field-particle-quadratic-drag = air resistance, quadratic
field-particle-quadratic-drag-help = Air resistance c: a force of c v² against the motion (a ball through air: c = ½ ρ C_d A)
field-particle-drag-coefficient = drag coefficient
field-particle-drag-coefficient-help = C_d: air resistance ½ ρ C_d π r² v² from the world's air density and the radius (a ball: 0.47); instead of the quadratic c
field-particle-inertia = moment of inertia
field-particle-inertia-help = I/(m r²): 0 a point that never turns, 0.5 a solid disc, 1 a thin ring
field-particle-spin = spin
field-particle-spin-help = Angular velocity ω, counter-clockwise positive (a turning particle's)
field-particle-angle = angle
field-particle-angle-help = Orientation, counter-clockwise: where the turning particle's marked radius points
field-particle-color = colour
field-particle-color-help = Display colour, "#rrggbb"
field-spring-from = from
field-spring-from-help = A particle's name, or a fixed point [x, y]
field-spring-to = to
field-spring-to-help = A particle's name, or a fixed point [x, y]
field-spring-stiffness = stiffness
field-spring-stiffness-help = k, 0 or more
field-spring-natural-length = natural length
field-spring-natural-length-help = The length at which the spring exerts no force
field-spring-damping = damping
field-spring-damping-help = b: force −b·(relative velocity along the spring)
field-rod-from = from
field-rod-from-help = A particle's name, or a fixed point [x, y]
field-rod-to = to
field-rod-to-help = A particle's name, or a fixed point [x, y]
field-rod-length = length
field-rod-length-help = The distance the rod keeps between its ends
field-string-from = from
field-string-from-help = A particle's name, or a fixed point [x, y]
field-string-to = to
field-string-to-help = A particle's name, or a fixed point [x, y]
field-string-length = length
field-string-length-help = The farthest apart the string lets its ends go
field-string-restitution = restitution
field-string-restitution-help = When it snaps taut: 0 (the ends stop separating) to 1 (they bounce back)
field-ramp-from = from
field-ramp-from-help = One end of the ramp
field-ramp-to = to
field-ramp-to-help = The other end
field-ramp-thickness = thickness
field-ramp-thickness-help = The ramp is every point within half this of its segment
field-ramp-restitution = restitution
field-ramp-restitution-help = 0 (no bounce) to 1 (perfectly elastic)
field-ramp-friction = friction
field-ramp-friction-help = Coefficient of static and kinetic friction
inspector-name = name
inspector-name-hint = Unique among all objects
inspector-rod-length-differs = Its ends are { $distance } m apart at the start, not { $length } m: the rod pulls them onto its length before the first step.
inspector-string-too-short = Its ends are { $distance } m apart at the start, more than its { $length } m: the string pulls them onto its length before the first step.
inspector-bounds-min-hint = The box's lower-left corner
inspector-bounds-max-hint = The box's upper-right corner
inspector-fixed-point = fixed point
inspector-end-hint = A particle, or a fixed point in the world
inspector-end-point = { $end } point
inspector-end-point-hint = The fixed point, metres

## Graphs, the status line, edits (Undo and Redo), file errors
notice-no-example = there is no example '{ $name }'
notice-cannot-read-in-browser = cannot read '{ $path }' in the browser
status-frame-time = frame { $ms } ms
status-objects = { $particles } particles, { $springs } springs, { $ties } rods and strings, { $ramps } ramps
edit-set = set { $what }
edit-add-graph = add graph
edit-remove-graph = remove graph
edit-add-series = add series
edit-remove-series = remove series
edit-set-x-axis = set x axis
edit-paste = paste
edit-move-group = move selection
edit-delete-group = delete selection
edit-set-time-scale = set time scale
edit-set-integrator = set integrator
edit-set-time-step = set time step
edit-edit-from-here = edit from here
edit-move-particle = move particle
edit-move-ramp = move ramp
edit-move-ramp-end = move ramp end
edit-set-velocity = set velocity
edit-add-particle = add particle
edit-add-spring = add spring
edit-add-rod = add rod
edit-add-string = add string
edit-add-ramp = add ramp
edit-rename = rename
edit-delete-particle = delete particle
edit-delete-spring = delete spring
edit-delete-rod = delete rod
edit-delete-string = delete string
edit-delete-ramp = delete ramp
graph-untitled = Graph { $number }
graph-figure-title = { $y } against { $x }
graph-particle = particle
graph-particle-hint = The particle whose quantity to add
graph-quantity = quantity
graph-quantity-hint = The quantity to add
graph-tension-hint = Plot the force this rod or string carries (pulling is positive)
graph-marks = extremes and zeros
graph-marks-hint = Mark each series' maxima, minima and zero crossings, located in the run once it stops (stepped to, as the stopwatch's events; read off the samples while it plays and in a very large scene), and give the period from successive maxima
graph-earlier-runs = earlier runs
graph-forget-earlier = forget earlier runs
graph-forget-earlier-hint = The grey curves are the runs before the last (up to three, kept from Play to Play); forget them
graph-fit = fit
graph-fit-hint = Fit each series with a model by least squares: its parameters with their standard uncertainties, and the curve dashed
graph-fit-none = none
graph-fit-line = line a + b x
graph-fit-parabola = parabola a + b x + c x²
graph-fit-sine = sine A sin(ω x + φ) + c
graph-fit-decay = decay A e^(−x/τ) + c
graph-fit-result = { $quantity }, { $model }: { $parameters } (rms residual { $rms })
graph-reset-view = reset view
graph-reset-view-hint = Show the whole run again (Ctrl and the mouse wheel zoom, a drag pans)
graph-period = period of { $quantity }: { $period } s (mean of { $cycles } { $cycles ->
    [one] cycle
   *[other] cycles
} of { $maxima } { $maxima ->
    [one] maximum
   *[other] maxima
}, { $how ->
    [located] located in the run
   *[sampled] read off the samples
})
graph-period-too-few = period of { $quantity }: not yet ({ $count } maxima; a third tells whether they repeat)
graph-period-irregular = period of { $quantity }: none can be told (its { $count } maxima repeat at no regular cycle)
graph-angle-hint = Plot this rod's, string's or spring's angle from the downward vertical (counter-clockwise positive)
graph-length-hint = Plot the distance between this rod's, string's or spring's ends
graph-total-hint = Plot this system quantity
graph-x-axis-now = x axis: { $quantity }
graph-remove-series-hint = Remove this series
impacts-go-to-hint = Show the run at this impact
units-comes-to = it comes to { $value }
units-empty = it is empty
units-brackets = its brackets do not match
units-ends-with-operator = it ends with an operator
units-unknown-word = '{ $word }' is no function, constant or unit of this field
units-unreadable = it cannot be read as arithmetic
expression-too-long = an expression of { $length } characters is longer than any formula NewtonLab reads (at most { $most })
expression-too-deep = an expression with brackets { $depth } deep is deeper than any formula NewtonLab reads (at most { $most })
units-not-a-number = "{ $text }" is not a number: { $reason }; write a number or arithmetic like 2*pi or sqrt(2)/2
units-not-a-number-unit = "{ $text }" is not a number: { $reason }; write a number or arithmetic like 2*pi or sqrt(2)/2, with a unit such as { $units }
file-cannot-read = cannot read '{ $path }': { $error }
file-cannot-write = cannot write '{ $path }': { $error }
file-cannot-read-file = cannot read '{ $path }'
file-cannot-download = the browser could not download '{ $path }'
file-cannot-autosave = cannot autosave in '{ $path }': { $error }
file-cannot-encode = the picture could not be encoded: { $error }
reading-full = { $value } (the full value: click to copy it)
reading-copied = { $value } copied to the clipboard.
experiments-heading = Experiment series
experiments-heading-hint = Vary a value of the scene, run once for each value, and plot what each run measured against it, with the law expected
experiment-add = Add an experiment series
experiment-add-hint = A series for the selected particle (or the first): its launch angle from 15° to 75°, measuring its highest point; change any field
experiment-none = There is no such experiment series.
experiment-title = Series { $number }
experiment-figure-title = { $measure } against { $vary }
experiment-remove = remove
experiment-remove-hint = Remove this series from the scene
experiment-vary = vary
experiment-vary-hint = The value varied, as the scene file names it: Ball.velocity.angle, Bob.mass, world.gravity.y, simulation.time_step
experiment-from = from
experiment-from-hint = The first value
experiment-to = to
experiment-to-hint = The last value (reached when the steps reach it)
experiment-step = step
experiment-step-hint = The step between values
experiment-until = until (s)
experiment-until-hint = How long each run lasts, seconds of simulated time
experiment-measure = measure
experiment-measure-hint = What each run is measured for, separated by ";": Ball.x at Ball.y crosses 0 down, t at Bob.vx crosses 0 #3, max Ball.y, min Ball.vy, period Bob.x, Ball.x at 1.5
experiment-theory = theory
experiment-theory-hint = Optional: the first measure's law, in x (or a: the varied value, an angle in radians) and the scene's constants g, m, r, v0, h, b, c (the varied particle's), L, k. v0^2*sin(2*a)/g is a projectile's range
experiment-run = Run the series
experiment-run-hint = Run the scene once for each value (on every core) and plot the measures
experiment-progress = { $done } of { $total } runs
experiment-took = { $runs } runs in { $seconds } s
experiment-export-csv-hint = The results as CSV: the varied value, then each measure (as newtonlab sweep writes them)
experiment-residuals = { $measure } − theory: at most { $worst }
experiment-residual = measured − theory
experiment-theory-curve = theory: { $law }
edit-add-experiment = add experiment series
edit-change-experiment = change experiment series
edit-remove-experiment = remove experiment series
experiment-choose = choose…
experiment-choose-hint = Pick the value to vary among the selected particle's (or the first's) and the world's
experiment-add-measure = add a measure…
experiment-add-measure-hint = Add a measure often wanted, for the selected particle (or the first) and each rod or string; edit it in the field
scene-clock-too-coarse = the time step { $step } s is too fine for a clock at { $start } s: an instant there is rounded by more than 1e-4 of a step (make the time step at least a trillionth of the start time, or start nearer 0)
scene-same-point = starts at the same point as particle '{ $other }', where the force between them is infinite: move one, or give [world] a softening
cli-every-too-fine = --every { $every } is too fine for instants as far as { $until } s: the row times k × every would run together (choose a larger --every)
cli-state-not-saveable = the state at { $time } s cannot be saved as a scene that reopens: { $problem }
total-kinetic-energy = kinetic energy
total-potential-energy = potential energy
total-total-energy = total energy
total-momentum-x = momentum x
total-momentum-y = momentum y
total-angular-momentum = angular momentum
cli-not-a-file = '{ $source }' is not a file (a directory, a device or a pipe): give a scene file, or example:NAME
cli-file-too-large = '{ $source }' is { $megabytes } MB: a scene file may be at most { $most } MB
cli-same-output = { $first } and { $second } both name '{ $path }': their rows would interleave; give each its own file
scene-inside-ramp = starts with its centre inside ramp '{ $ramp }': place it outside the ramp (on it, it rests there)
cli-too-much-work = --until { $until } would take { $steps } steps of { $particles } moving particles, { $work } particle-steps, more than { $most } (minutes to hours of work); choose a larger time_step, a shorter --until or fewer particles, or give --no-limit
run-tie-not-held = at t = { $time } s rod or string '{ $tie }' could not be held at its length: the forces on it are too strong for the time step, its ends' masses too unequal, or its length cannot hold with the others'; choose a smaller time_step or check the lengths and masses
run-pulley-reached = at t = { $time } s body '{ $body }' reached the wheel of pulley '{ $pulley }': its side of the string has run out (stop the run before, or hang the body lower)
run-tie-too-far = at t = { $time } s rod or string '{ $tie }' lies too far from the origin for its length of { $length } m: the rounding of its ends' positions alone keeps it from being held to a billionth of its length; place the scene nearer the origin or make the link longer
run-drag-too-strong = at t = { $time } s the air resistance on particle '{ $particle }' slows it by e every { $decay } s, faster than a time step of { $step } s can follow (the method would make energy from nothing); choose a time_step of at most that, or dopri5
run-left-bounds = at t = { $time } s particle '{ $particle }' left the world's bounds at { $speed } m/s, too fast for the time step to resolve its impacts with the walls; choose a smaller time_step
scene-got-null = null
scene-json-duplicate-key = the key '{ $key }' appears twice in one object; keep one
scene-number-beyond-f64 = { $text } is beyond what a 64-bit number holds (about 2.2e-308 to 1.8e308 in size, or 0)
file-save-changes = Save
file-save-changes-hint = Save the changes, then go on
scene-body-shape = shape must be "box" or "polygon", got "{ $got }"
scene-must-be-points = must be a list of points, like [[0.0, 0.0], [0.4, 0.0], [0.2, 0.3]], got { $got }
scene-body-box-size = a box needs a { $field } greater than 0
scene-body-not-box = { $field } is a box's: a polygon's outline is its vertices (leave { $field } out)
scene-body-vertex-count = a polygon needs 3 to { $most } vertices, got { $count }
scene-body-vertex-not-finite = vertex { $k } is not a finite point of a size NewtonLab simulates (at most 1e100)
scene-body-repeated-vertex = vertices { $a } and { $b } are the same point: leave one out
scene-body-collinear = vertices { $a }, { $b } and { $c } lie on one line: leave out the middle one
scene-body-clockwise = the vertices go clockwise: list them counter-clockwise (reverse the list)
scene-body-concave = the outline is not convex at vertex { $k }: a body must be convex (build a concave shape from several bodies)
scene-body-winds = the outline crosses itself (it goes round more than once): list the corners in order round the outline
scene-body-no-mass = needs a mass (kg) or a density (kg/m²)
scene-body-mass-and-density = give a mass or a density, not both
scene-body-static-friction = static_friction { $static } must be at least the kinetic friction { $kinetic }
scene-body-overlap = overlaps body '{ $other }' at the start: move one of them apart
scene-motor = motor must be {"{"} torque = N·m {"}"} or {"{"} spin = rad/s, max_torque = N·m {"}"}
scene-joint-no-body = there is no body '{ $name }' (pins, hinges and pulleys hold bodies, [[body]])
scene-joint-particle = '{ $name }' is a particle: pins, hinges and pulleys hold bodies ([[body]]), not yet particles; tie particles with a rod or a string
scene-hinge-itself = a hinge joins two bodies, and a and b are both '{ $body }'
scene-joint-twice = holds the same bodies at the same point as '{ $other }': leave one out
scene-joint-fixed = holds nothing that can move: every body it joins is fixed
scene-joint-anchor = { $field } is not at the joint's point at: leave it out, and it is found from at
scene-pulley-same = a pulley's string joins two bodies, and a and b are both '{ $body }'
scene-pulley-inside = body '{ $body }' is at the wheel: it must hang clear of the pulley's wheel
scene-force-unreadable = '{ $text }' is no expression: write one of x, y, vx, vy, t, m, q with numbers, + − * / ^, sqrt, sin, cos, exp, … (for example -2*x - 0.5*x^3)
scene-force-unknown-name = names '{ $name }': a force may name { $names }
scene-force-potential-name = names '{ $name }': a potential energy is of the position alone and may name { $names }
scene-force-on-body = '{ $name }' is a body: forces of one's own act on particles
scene-force-on-nothing = there is no particle '{ $name }'
scene-force-not-finite = on particle '{ $particle }' where it starts the force is ({ $x }, { $y }) N, not a finite force
scene-force-potential-of-motion = a potential energy belongs to a force of the position alone, and this force names the velocity or the time: leave the potential out
scene-force-potential-mismatch = at particle '{ $particle }''s start the potential's −∇U is ({ $ux }, { $uy }) N but the force is ({ $fx }, { $fy }) N: the energy books would not close; give the potential of this force, or none
scene-limits = limits must be [lower, upper] in degrees
scene-limits-order = limits must be finite with the lower below the upper, got [{ $lower }, { $upper }]
scene-limits-start = the joint's angle at the start, { $angle }°, is outside its limits
cli-check-body = body '{ $name }': { $shape }, area { $area } m², mass { $mass } kg, moment of inertia { $inertia } kg·m² about its centroid, at { $centroid } m in the outline as typed
cli-check-pin = pin '{ $name }': holds body '{ $body }' at { $at } m; its moment of inertia about the pin is { $inertia } kg·m²
cli-check-hinge = hinge '{ $name }': joins body '{ $b }' to body '{ $a }' at { $at } m
cli-check-pulley = pulley '{ $name }': a string from body '{ $a }' over a wheel of radius { $radius } m and { $mass } kg at { $at } m to body '{ $b }'
cli-check-force = force '{ $name }': ({ $fx }, { $fy }) N on { $on }; no potential, so the ledger's residual holds its work
cli-check-force-potential = force '{ $name }': ({ $fx }, { $fy }) N on { $on }, with its potential energy
cli-check-force-everything = every particle
cli-check-magnetic = magnetic field B_z = { $field } T on { $charged } charged particles (q v × B: it turns them and does no work)
cli-check-joints-start = the bodies' velocities at the start move their joints apart: the run starts from the nearest velocities the joints allow, { $lost } J of kinetic energy less (give a hinged body its partner's velocity at the hinge)
cli-check-motor-torque = , driven by a motor of { $torque } N·m
cli-check-motor-spin = , driven by a motor to { $spin } rad/s with at most { $torque } N·m
cli-check-bodies-free = bodies strike, rest on and slide on the walls, the ramps and each other (the smaller restitution, the frictions' geometric mean between two bodies); pinned and hinged bodies meet nothing yet; bodies do not yet meet particles, and springs, rods and strings do not attach to them
edit-move-body = move body
edit-add-body = add body
edit-delete-body = delete body
edit-add-pin = add pin
edit-delete-pin = delete pin
edit-add-hinge = add hinge
edit-delete-hinge = delete hinge
edit-add-pulley = add pulley
edit-delete-pulley = delete pulley
edit-add-force = add force
edit-delete-force = delete force
tool-box = Box
tool-box-hint = Drag corner to corner to draw a rigid box (7)
field-body-width = width
field-body-width-help = A box's extent along its own x
field-body-height = height
field-body-height-help = A box's extent along its own y
field-body-mass = mass
field-body-mass-help = Mass, greater than 0 (or give the density instead)
field-body-density = density
field-body-density-help = Mass per area: the shape's area gives the mass
field-body-position = position
field-body-position-help = The centroid
field-body-angle = angle
field-body-angle-help = Orientation, counter-clockwise
field-body-velocity = velocity
field-body-velocity-help = The centroid's velocity
field-body-spin = spin
field-body-spin-help = Angular velocity ω, counter-clockwise positive
field-body-restitution = restitution
field-body-restitution-help = 0 (no bounce) to 1 (perfectly elastic)
field-body-friction = friction
field-body-friction-help = Kinetic coefficient of friction
field-body-fixed = fixed
field-body-fixed-help = A fixed body never moves
field-body-color = colour
field-body-color-help = Display colour, "#rrggbb"
status-bodies = { $bodies } bodies
tool-polygon = Polygon
tool-polygon-hint = Click the corners of a rigid convex polygon; click the first again to close it (8)
lesson-no-title = a lesson needs a title
lesson-text-too-long = the text is { $size } KiB; a lesson's text may hold at most { $most } KiB (a picture belongs beside the scene, not in it)
lesson-html = the text holds HTML (a tag such as <script> or <img>), which a lesson never shows or runs: write Markdown, and in a formula put a space after <
lesson-bad-id = the id '{ $id }' must be letters, digits, _ or - (it is what an answer names: ID=VALUE)
lesson-repeated-id = the id '{ $id }' is used by an earlier question
lesson-no-prompt = a question needs a prompt
lesson-unit-misfit = the unit '{ $unit }' does not fit the measure, which is in { $si }
lesson-tolerance = tolerance must be greater than 0, got { $tolerance }
lesson-slider-range = min { $min } must be less than max { $max }
lesson-slider-step = step must be greater than 0 and at most max − min, got { $step }
lesson-slider-rule = at { $value } the scene breaks a rule: { $why }
cli-check-lesson = lesson '{ $title }': { $sliders } slider(s), { $questions } question(s)
cli-lesson-none = { $source } has no [lesson]: give a scene file with one, or an example lesson (newtonlab examples)
cli-lesson-answer-malformed = --answer '{ $text }' must be ID=VALUE, such as { $first }="1.5 s"; the ids: { $ids }
cli-lesson-unknown-id = --answer '{ $text }': the lesson has no question of that id; its { $count } question(s): { $ids }
cli-lesson-answer-unreadable = --answer for '{ $id }' must be a quantity in { $unit } (or another unit of its kind): { $why }
cli-lesson-unmeasured = the simulation cannot answer question '{ $id }': { $why }
menu-lesson = Lesson
menu-lesson-hint = Show or hide the lesson: its instructions, sliders and questions
key-lesson = Show or hide the lesson
edit-slide = move a lesson's slider
inspector-about = About this scene
lesson-sliders = Try changing
lesson-sliders-reset = Reset the run to change these
lesson-questions = Questions
lesson-answer-hint = your answer, in { $unit }
lesson-check = Check
lesson-right = Right
lesson-close = Close — check your measurement
lesson-not-yet = Not yet — measure again
lesson-revealed = The simulation measures { $value }.
worksheet-no-lesson = the scene has no lesson: a worksheet is a lesson's ([lesson] in the scene file)
worksheet-no-font = the bundled font could not be read for the worksheet
worksheet-no-picture = the scene's picture has no size
worksheet-failed = the worksheet could not be written: { $why }
worksheet-name = Name:
worksheet-sliders = You may change
worksheet-slider = { $field }: from { $min } to { $max }{ $unit }, in steps of { $step }
worksheet-key-title = Answer key: { $title }
worksheet-key-line = { $id }: { $value } { $unit } (right within ± { $tolerance }, close within ± { $close })
worksheet-key-none = { $id }: the simulation gives no value: { $why }
menu-worksheet = Export worksheet…
menu-worksheet-hint = The lesson as a worksheet to print (PDF): its instructions, a picture of the scene and its questions with lines for the answers
menu-answer-key = Export worksheet with answer key…
menu-answer-key-hint = The worksheet, then the simulation's value of every question on a page of its own (PDF)
file-title-pdf = Export the worksheet (PDF)
notice-worksheet-saved = Worksheet written to { $path }
menu-fields = Fields and forces
menu-bodies = Rigid bodies
menu-lessons = Lessons
