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
menu-save-canvas-hint = A picture of the canvas as it is on screen
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
key-play-pause = Play or pause
key-step = One step forward
key-step-back = One step back in the run
key-reset = Reset to the scene as built
key-fit = Fit the view to the scene
key-stopwatch = Stopwatch
key-inspector = Show or hide the inspector
key-graphs = Show or hide the graphs
key-projector = Projector mode
key-help = This list of keys
canvas-key-focus = Give the canvas the keyboard
canvas-key-cycle = Select the next / previous object
canvas-key-move = Move the selected particle or ramp one grid step
canvas-key-fine = Move it a tenth of a grid step
canvas-key-enter = Add the current tool's object at the view's centre (a spring, rod or string from the selected particle)
canvas-key-escape = Give the keyboard back; Tab then moves to the next control
canvas-key-instrument-enter = With the tape (M) or the protractor (A): lay it from the selected particle to the next ones, or at the view's centre
canvas-key-instrument-tab = With the tape or the protractor: pick the end or point the arrow keys move
canvas-key-instrument-move = With the probe, tape or protractor: move it (its chosen point) a tenth of a grid step; Shift a hundredth

## Readouts and graphs
readout-heading = Energy and momentum
readout-failed = The run failed: the values of its last good sample.
readout-potential = potential (J)
readout-potential-field = potential: field (J)
readout-potential-springs = potential: springs (J)
readout-potential-gravitation = potential: gravitation (J)
readout-potential-electrostatic = potential: electrostatic (J)
readout-press-play = Press Play to see the energies and momentum.
readout-kinetic = kinetic (J)
readout-total = total (J)
readout-total-at-play = total at Play (J)
readout-damping = taken by damping (J)
readout-friction = taken by friction (J)
readout-impacts = taken by impacts (J)
readout-ties = work of rods and strings (J)
readout-error = numerical error
readout-momentum = momentum (kg·m/s)
bar-kinetic = kinetic
bar-damping = damping took
bar-friction = friction took
bar-impacts = impacts took
bar-total-at-play = total at Play
bars-title = Energy bars
bars-hint = Each kind of energy to one scale; the numbers are in the table above
impacts-title = Impacts ({ $count })
impacts-none = No impacts yet.
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
graph-save-png-hint = Save a picture of this graph as it is on screen
graph-press-play = Press Play: the graph fills from the start of the run.

## Announcements for screen readers
announce-impact = At { $time } s, { $particle } hit { $other }.{ $more ->
    [0] {""}
    [one] {" "}And 1 more impact since the last message.
   *[other] {" "}And { $more } more impacts since the last message.
}
announce-wall = the wall
