# Los textos de NewtonLab en español (modelo: i18n/en/newtonlab.ftl).

## Menus
menu-file = Archivo
menu-file-hint = Nuevo, abrir, guardar, compartir
menu-new = Nuevo
menu-new-hint = Una escena vacía
menu-open = Abrir…
menu-open-hint = Abrir un archivo de escena
menu-save = Guardar
menu-save-hint = Guardar la escena
menu-save-canvas = Guardar el lienzo como PNG…
menu-save-canvas-hint = Una imagen del lienzo tal como se ve, al doble de la resolución de la pantalla para imprimir (en el navegador, como en pantalla)
menu-save-as = Guardar como…
menu-save-as-hint = Guardar la escena con otro nombre
menu-copy-link = Copiar un enlace a esta escena
menu-copy-link-hint = Un enlace que abre esta escena: en la barra de direcciones y en el portapapeles
menu-link-copied = Un enlace a esta escena está en la barra de direcciones y en el portapapeles.
menu-edit = Editar
menu-edit-hint = Deshacer, rehacer, borrar
menu-undo = Deshacer
menu-undo-what = Deshacer: { $what }
menu-undo-hint = Deshacer el último cambio
menu-redo = Rehacer
menu-redo-what = Rehacer: { $what }
menu-redo-hint = Rehacer lo deshecho
menu-delete = Borrar
menu-delete-hint = Quitar el objeto seleccionado
menu-cut = Cortar
menu-cut-hint = Copiar el objeto seleccionado y luego quitarlo
menu-copy = Copiar
menu-copy-hint = Copiar el objeto seleccionado (un muelle, barra o cuerda con las partículas que une) como texto de escena
menu-paste = Pegar
menu-paste-hint = Añadir lo copiado junto a donde estaba, renombrado donde los nombres estén ocupados (Ctrl+V pega también texto de escena de otros programas)
menu-duplicate = Duplicar
menu-duplicate-hint = Copiar el objeto seleccionado y pegarlo a su lado
menu-examples = Ejemplos
menu-examples-hint = Abrir una escena incluida (los experimentos del informe y más)
menu-view = Ver
menu-view-hint = Encuadre, paneles, modo proyector, idioma
menu-fit = Encuadrar
menu-fit-hint = Encuadrar la escena y las trayectorias recientes
menu-inspector = Inspector
menu-inspector-hint = Mostrar u ocultar el inspector
menu-graphs = Gráficas
menu-graphs-hint = Mostrar u ocultar las gráficas y las lecturas
menu-projector = Modo proyector
menu-projector-hint = Solo el lienzo, con letra grande, para una clase
menu-follow = Seguir
menu-follow-hint = Mantener a la vista una partícula, o todas, durante la reproducción
menu-language = Idioma
menu-language-hint = El idioma de la aplicación; cambia al instante
menu-text-size = Tamaño del texto
menu-text-size-hint = Texto y controles más grandes; se recuerda para la próxima vez
menu-high-contrast = Alto contraste
menu-high-contrast-hint = Negro sobre blanco con contornos marcados; se recuerda para la próxima vez
menu-measure = Medir
menu-measure-hint = Cinta métrica, sonda de campo, vista del campo
menu-no-field = Sin vista del campo
menu-electric-field = Campo eléctrico
menu-gravitational-field = Campo gravitatorio
menu-field-hint = Flechas del campo de las partículas sobre el lienzo, más oscuras donde es más intenso
menu-stopwatch = Cronómetro
menu-stopwatch-hint = Tiempo simulado entre dos sucesos: a mano, un choque, una partícula que cruza la cinta
menu-clear-measurements = Quitar las mediciones
menu-clear-measurements-hint = Retirar la cinta, la sonda y el transportador
menu-help = Ayuda
menu-keys = Teclas
menu-keys-hint = Todos los atajos y cómo usar el lienzo con el teclado
menu-getting-started = Primeros pasos
menu-getting-started-hint = Tres tareas cortas: colocar y ejecutar, medir, graficar
start-title = Primeros pasos
start-intro = Tres tareas cortas, de un minuto cada una, para orientarse. Ayuda › Primeros pasos abre de nuevo esta página; F1 muestra todas las teclas.
start-place = Colocar y ejecutar
start-place-1 = Archivo › Nuevo: una escena vacía, con gravedad.
start-place-2 = Pulse 2 (Partícula) y haga clic en el lienzo: una bola de 1 kg.
start-place-3 = En el Inspector de la izquierda, escriba una velocidad x de 3 (también con unidades: 30 km/h).
start-place-4 = La barra espaciadora reproduce y pausa; R vuelve a la escena tal como la construyó.
start-measure = Medir
start-measure-1 = Ejemplos › Pendulum on a rod, released at 60°; barra espaciadora, y tras una o dos oscilaciones otra vez.
start-measure-2 = Bajo la gráfica, marque extremos y ceros: muestra el período, 3,044625 s, como da la teoría.
start-measure-3 = retorno » en la barra del tiempo muestra el péndulo exactamente en su siguiente punto de retorno.
start-graph = Graficar
start-graph-1 = Añadir una gráfica, elija una partícula y una magnitud, y luego Añadir.
start-graph-2 = Elija vx y Usar como eje x: un diagrama de fase. Una serie añadida después también tiene toda la ejecución.
start-graph-3 = Exportar CSV… guarda cada muestra para una hoja de cálculo.

## Tool bar
toolbar-play = Reproducir
toolbar-pause = Pausa
toolbar-play-hint = Iniciar o pausar la simulación (Espacio)
toolbar-step = Paso
toolbar-step-hint = Avanzar un paso de tiempo (.)
toolbar-reset = Reiniciar
toolbar-reset-hint = Volver a la escena tal como se editó (R)
toolbar-time-scale-hint = Escala de tiempo: segundos simulados por segundo real (0,01× a 100×)
toolbar-integrator-hint = Cómo se integra el movimiento en el tiempo
toolbar-time-step-hint = Paso de tiempo, en segundos (dopri5: el paso más largo)
toolbar-fit-hint = Encuadrar la escena y las trayectorias recientes (F)
toolbar-velocity = velocidad
toolbar-velocity-hint = Flechas de velocidad (la punta: dónde estará la partícula en 0,5 s)
toolbar-acceleration = aceleración
toolbar-acceleration-hint = Flechas de aceleración
toolbar-force = fuerza
toolbar-force-hint = Flechas de la fuerza neta (la longitud crece con el logaritmo de la fuerza)
toolbar-trails = estelas
toolbar-trails-hint = Las trayectorias recientes de las partículas
toolbar-names = nombres
toolbar-names-hint = Los nombres de los objetos
follow-nothing = nada
follow-nothing-hint = Una cámara fija
follow-all = todas las partículas
follow-all-hint = Mantener a la vista todas las partículas
follow-particle-hint = Mantener esta partícula en el centro

## Tools
tool-select = Seleccionar
tool-particle = Partícula
tool-spring = Resorte
tool-rod = Varilla
tool-string = Cuerda
tool-ramp = Rampa

## Status line
status-behind = funcionando a { $ratio }× de la velocidad pedida ({ $real }× tiempo real)
status-real-time = { $real }× tiempo real
status-paused = en pausa
status-editing = edición
status-stopped = detenido: { $failure }; se muestra el último estado válido

## Keys (F1)
keys-title = Teclas
keys-everywhere = En todas partes (salvo al escribir en un campo)
keys-canvas = En el lienzo
keys-controls = Tab y Mayús+Tab pasan de un control a otro; Intro o Espacio pulsan un botón; los menús se abren con un clic o, con el foco, con Intro.
key-new = Escena nueva
key-open = Abrir un archivo de escena
key-save = Guardar
key-save-as = Guardar como
key-undo = Deshacer
key-redo = Rehacer
key-delete = Borrar el objeto seleccionado
key-duplicate = Duplicar el objeto seleccionado
key-play-pause = Reproducir o pausar
key-step = Un paso adelante
key-step-back = Un paso atrás en la ejecución
key-next-turn = Siguiente punto de retorno de la partícula seleccionada
key-previous-turn = Punto de retorno anterior de la partícula seleccionada
key-reset = Volver a la escena construida
key-fit = Ajustar la vista a la escena
key-stopwatch = Cronómetro
key-inspector = Mostrar u ocultar el inspector
key-graphs = Mostrar u ocultar las gráficas
key-projector = Modo proyector
key-help = Esta lista de teclas
key-next-region = El foco a la región siguiente: menú, barra de herramientas, lienzo, inspector, gráficas, barra del tiempo
key-previous-region = El foco a la región anterior
canvas-key-focus = Dar el teclado al lienzo
canvas-launch = { $speed } a { $angle }°
canvas-key-cycle = Seleccionar el objeto siguiente / anterior
canvas-key-move = Mover la partícula o la rampa seleccionada un paso de la cuadrícula
canvas-key-fine = Moverla una décima de paso
canvas-key-enter = Añadir un objeto de la herramienta actual en el centro de la vista (un resorte, una varilla o una cuerda desde la partícula seleccionada)
canvas-key-escape = Devolver el teclado; Tab pasa entonces al control siguiente
canvas-key-instrument-enter = Con la cinta (M) o el transportador (A): tenderlo desde la partícula seleccionada hasta las siguientes, o en el centro de la vista
canvas-key-instrument-tab = Con la cinta o el transportador: elegir el extremo o el punto que mueven las flechas
canvas-key-instrument-move = Con la sonda, la cinta o el transportador: moverlo (su punto elegido) una décima de paso; Mayús una centésima
canvas-key-add = Añadir un objeto a la selección, o quitarlo
canvas-key-box = Seleccionar lo que queda en un recuadro trazado desde un espacio vacío

## Readouts and graphs
readout-heading = Energía y momento
readout-failed = La ejecución falló: los valores de su última muestra válida.
readout-potential = potencial (J)
readout-potential-field = potencial: altura, m g h (J)
readout-potential-springs = potencial: resortes (J)
readout-potential-gravitation = potencial: gravitación (J)
readout-potential-electrostatic = potencial: electrostática (J)
readout-potential-own = potencial: fuerzas propias (J)
readout-press-play = antes de reproducir
readout-at = En t = { $time }
readout-kinetic = cinética (J)
readout-total = total (J)
readout-total-at-play = total al reproducir (J)
readout-damping = tomada por el amortiguamiento (J)
readout-friction = tomada por el rozamiento (J)
readout-impacts = tomada por los choques (J)
readout-drag = tomada por la resistencia del aire (J)
readout-motors = aportado por motores (J)
readout-ties = trabajo de varillas y cuerdas (J)
readout-error = error numérico
readout-momentum = momento (kg·m/s)
bar-kinetic = cinética
bar-damping = el amortiguamiento tomó
bar-friction = el rozamiento tomó
bar-impacts = los choques tomaron
bar-drag = la resistencia del aire tomó
bar-motors = aportado por motores
bar-total-at-play = total al reproducir
bars-title = Barras de energía
bars-hint = Cada tipo de energía a la misma escala; los números están en la tabla de arriba
impacts-title = Choques ({ $count })
impacts-none = Todavía no hay choques.
impacts-time = t (s)
impacts-particle = partícula
impacts-hit = chocó con
impacts-impulse = impulso (N·s)
impacts-lost = perdida (J)
impacts-a-ramp = una rampa
impacts-wall = pared
graph-add = Añadir una gráfica
graph-add-hint = Una gráfica nueva de magnitudes frente al tiempo
graph-remove = Quitar la gráfica
graph-remove-hint = Quitar esta gráfica (sus datos siguen grabados)
graph-add-series = Añadir
graph-add-series-hint = Dibujar esta magnitud
graph-x-axis = Usar como eje x
graph-x-axis-hint = Dibujarlo todo frente a esta magnitud (un diagrama de fases)
graph-use-time = usar el tiempo
graph-use-time-hint = Volver a dibujar frente al tiempo
graph-export-csv = Exportar CSV…
graph-export-csv-hint = Guardar todas las muestras grabadas de las magnitudes de esta gráfica como archivo CSV
graph-save-png = Guardar PNG…
graph-save-png-hint = Guardar esta gráfica como figura para imprimir: 1200 × 800 píxeles, con su título, ejes, números, unidades y leyenda
graph-save-svg = Guardar SVG…
graph-save-svg-hint = Guardar esta gráfica como figura para imprimir en SVG: se escala a cualquier tamaño
graph-press-play = Pulse Reproducir: la gráfica se llena desde el inicio de la ejecución.

## Announcements for screen readers
announce-impact = A los { $time } s, { $particle } chocó con { $other }.{ $more ->
    [0] {""}
    [one] {" "}Y 1 choque más desde el último mensaje.
   *[other] {" "}Y { $more } choques más desde el último mensaje.
}
announce-wall = la pared
announce-stretch = En { $time } s, el resorte { $spring } está en su máxima extensión, { $length } m.

## Instruments, tools, the timeline, the stopwatch, files, the inspector, links
instrument-tape = Cinta métrica
instrument-probe = Sonda de campo
instrument-protractor = Transportador
instrument-tape-hint = Arrastrar entre dos puntos para medir la distancia y la dirección; un extremo sobre una partícula la sigue (M)
instrument-probe-hint = Hacer clic en un punto para leer allí el campo gravitatorio y eléctrico y el potencial; las flechas la mueven (P)
instrument-protractor-hint = Arrastrar desde el vértice a lo largo del primer lado y otra vez para el segundo: el ángulo entre ellos; los extremos sobre partículas las siguen (A)
instrument-probe-at = en { $position } m
instrument-probe-vector = { $vector } { $unit }, módulo { $size } { $unit }
instrument-probe-gravitational-potential = potencial gravitatorio { $value } J/kg
instrument-probe-electric-potential = potencial eléctrico { $value } V
tool-select-hint = Seleccionar y mover objetos; arrastrar la punta de una flecha de velocidad para fijar la velocidad; arrastrar el espacio vacío para desplazar la vista (1)
tool-particle-hint = Hacer clic en el lienzo para colocar una partícula (2)
tool-spring-hint = Arrastrar de una partícula a otra, o al espacio vacío para un punto fijo (3)
tool-rod-hint = Una varilla rígida: arrastrar de una partícula a otra, o al espacio vacío para un punto fijo (5)
tool-string-hint = Una cuerda (floja si es más corta): arrastrar de una partícula a otra, o al espacio vacío para un punto fijo (6)
tool-ramp-hint = Arrastrar para dibujar una rampa (4)
stopwatch-by-hand = a mano
stopwatch-gate = cruzar la cinta
stopwatch-on-play = al pulsar Reproducir
stopwatch-impact = un choque
stopwatch-event = un evento
notice-invalid-values = No se ejecuta: algunos valores escritos no son válidos (en rojo en el inspector). Corríjalos primero:
    { $reasons }
notice-nothing-to-export = Todavía no hay nada que exportar: pulse Reproducir primero.
notice-paste-no-scene = Nada pegado: el portapapeles no contiene texto de escena ({ $reason })
notice-exported = { $rows } muestras exportadas a { $path }.
notice-settings-not-kept = No se pudieron guardar los ajustes: { $reason }
failure-reset = Restablecer la escena
status-physics-time = física { $ms } ms por fotograma
status-physics-time-hint = Tiempo de cálculo dedicado a la simulación en cada fotograma
inspector-title = Inspector
timeline-step-back = Paso atrás
timeline-before-play = La máquina del tiempo: pulse Reproducir y luego retroceda o vaya a cualquier momento de la ejecución
timeline-step-back-hint = Un paso de tiempo atrás en la ejecución (,)
timeline-slider-hint = Arrastrar a cualquier momento de la ejecución: se muestra exactamente como fue
timeline-time = t = { $now } s de { $last } s
timeline-to-end = Al final
timeline-to-end-hint = Volver a donde está la ejecución
timeline-previous-turn = « retorno
timeline-next-turn = retorno »
timeline-turn-hint = El punto de retorno anterior o siguiente de la partícula seleccionada ([ y ]): donde la x o la y de su velocidad pasa por 0, localizado exactamente
timeline-previous-impact = « choque
timeline-next-impact = choque »
timeline-impact-hint = El choque anterior o siguiente de la simulación, en su instante localizado
timeline-go-to = ir a
timeline-go-to-hint = Escriba un instante de la simulación (1.5, 1500 ms) y pulse Intro: se muestra exactamente
timeline-no-turn = Ningún punto de retorno ahí: seleccione una partícula cuya velocidad pase por 0 en la simulación.
timeline-no-impact = Ningún choque ahí en la simulación.
timeline-edit-from-here = Editar desde aquí
timeline-edit-from-here-hint = Convertir este momento en el inicio de la escena (posiciones, velocidades y tiempo), para cambiar algo y reproducir un futuro nuevo; se puede deshacer
stopwatch-title = Cronómetro
stopwatch-stopped = detenido
stopwatch-armed = esperando el inicio
stopwatch-running = en marcha
stopwatch-stop = Parar
stopwatch-start = Iniciar
stopwatch-reset = Reiniciar el cronómetro
stopwatch-start-on = iniciar
stopwatch-stop-on = parar
stopwatch-period-at-gate = periodo en la barrera
stopwatch-period-at-gate-hint = Iniciar en el 1.er cruce de la cinta, detener en el 3.º: un periodo completo de un péndulo que pasa por una barrera en su pivote
stopwatch-between-impacts = entre choques
stopwatch-between-impacts-hint = Iniciar en el 1.er choque, detener en el 2.º: el vuelo de un rebote
stopwatch-nth = n.º
stopwatch-nth-hint = Qué aparición, contada desde Iniciar: un periodo completo de un péndulo es el 1.º y el 3.º cruce de su vertical
stopwatch-event-label = evento
stopwatch-event-hint = MAGNITUD crosses VALOR, opcionalmente up o down: rod.angle crosses 0 down, bob.vx crosses 0
stopwatch-lap-mode = vueltas
stopwatch-lap-mode-hint = Seguir: cada parada es una vuelta, hasta pulsar Detener; se listan las vueltas y su media
stopwatch-mean = media { $mean } s de { $laps } vueltas
stopwatch-note = Tiempo simulado. Cada instante se localiza dentro del paso: choques, la barrera (el centro de una partícula cruza la cinta) y eventos, a un microsegundo o mejor.
graph-ask-hint = Añade a la lección una pregunta cuya respuesta es este periodo (la simulación comprueba con él las respuestas de la clase)
graph-ask-prompt = ¿Cuál es el periodo de { $quantity }?
stopwatch-ask = Preguntar por esto
stopwatch-ask-hint = Añade a la lección una pregunta cuya respuesta es esta medida: el tiempo desde Play hasta el evento (la simulación comprueba con ella las respuestas de la clase)
stopwatch-ask-prompt = ¿Cuánto tiempo después de Play ocurre esto: { $event }?
stopwatch-asked = Se añadió la pregunta { $id } a la lección; su enunciado y su tolerancia se editan en el archivo de la escena.
edit-ask = añadir una pregunta a la lección
lesson-untitled = Lección
notice-picture-saved = Imagen guardada en { $path }.
file-ok = Aceptar
file-ok-hint = Cerrar este mensaje (Intro)
file-changed-title = Cambiado en el disco
file-changed-body = «{ $path }» ha cambiado en el disco desde que se abrió. ¿Sobrescribirlo?
file-overwrite = Sobrescribir
file-overwrite-hint = Reemplazar el archivo del disco con esta escena
file-cancel = Cancelar
file-keep-hint = Conservar el archivo del disco; guardar con otro nombre
file-recover-title = Recuperar el trabajo no guardado
file-recover-body = NewtonLab se cerró la última vez con cambios sin guardar. ¿Recuperarlos?
file-recover-body-path = NewtonLab se cerró la última vez con cambios sin guardar en «{ $path }». ¿Recuperarlos?
file-recover = Recuperar
file-recover-hint = Abrir el trabajo no guardado
file-discard = Descartar
file-discard-hint = Tirar el trabajo no guardado
file-unsaved-title = Cambios sin guardar
file-unsaved-body = «{ $title }» tiene cambios sin guardar. ¿Guardarlos antes?
file-discard-changes = Descartar los cambios
file-discard-changes-hint = Perder los cambios sin guardar
file-keep-editing-hint = Seguir editando
file-verb-open = Abrir
file-verb-save = Guardar
file-verb-export = Exportar
file-title-open = Abrir una escena
file-title-save = Guardar la escena
file-title-csv = Exportar la gráfica como CSV
file-title-png = Guardar la imagen como PNG
file-title-svg = Guardar la figura como SVG
file-folder = carpeta
file-folder-hint = La carpeta
file-parent = .. (carpeta superior)
file-parent-hint = La carpeta superior
file-name = nombre del archivo
file-name-hint = El nombre del archivo ({ $extensions })
file-submit-hint = Este archivo: { $verb } (Intro)
file-close-hint = Cerrar sin hacer nada
inspector-use-cartesian = usar x, y
inspector-use-polar = usar polares
inspector-switch-hint = Mostrar este vector en la otra forma (el valor se conserva)
inspector-running = En marcha: Restablecer (R) para editar la escena.
inspector-selected = Seleccionado
inspector-selected-at-start = Seleccionado: como empieza la escena
inspector-delete = Eliminar
inspector-delete-hint = Quitar el objeto seleccionado (Supr)
inspector-world = Mundo
inspector-simulation = Simulación
inspector-live = En vivo: { $name }
inspector-tension = tensión
inspector-tension-hint = La fuerza que transmite: la tracción es positiva; 0 cuando está floja
inspector-work-done = trabajo realizado
inspector-no-work = 0 J (una ligadura no realiza trabajo)
inspector-live-position = posición
inspector-live-velocity = velocidad
inspector-live-acceleration = aceleración
inspector-live-speed = rapidez
inspector-live-kinetic-energy = energía cinética
inspector-live-momentum = momento lineal
inspector-live-spin = giro
inspector-live-angle = ángulo
inspector-live-rotational = de ella, de rotación
inspector-live-angular-momentum = momento angular
inspector-pair-forces-direct = directa (cada par, exacta)
inspector-pair-forces-tree = árbol (Barnes–Hut, para miles)
inspector-arithmetic-hint = Se convierten operaciones y unidades: 2*pi, sqrt(2)/2, 30 km/h, 5 cm, 250 g; coma o punto decimal
inspector-polar-angle = ángulo
inspector-polar-angle-hint = grados, en sentido antihorario desde +x
inspector-nothing-selected = Nada seleccionado: haga clic en un objeto del lienzo.
inspector-ramp-angle = pendiente
inspector-ramp-angle-hint = La dirección de su extremo «from» a su extremo «to», en grados en sentido antihorario desde +x (−30 baja hacia la derecha); al escribirla la rampa gira alrededor de «from»
inspector-ramp-length = longitud
inspector-ramp-length-hint = La distancia entre sus extremos; al escribirla «to» se mueve a lo largo de la pendiente
inspector-on-ramp = sobre la rampa
inspector-on-ramp-hint = La rampa sobre la que poner esta partícula
inspector-put-on-ramp = Ponerla encima
inspector-put-on-ramp-hint = Mover la partícula para que toque la cara superior de la rampa, a la distancia indicada abajo desde su extremo «from»
inspector-along-ramp = a lo largo
inspector-along-ramp-hint = A qué distancia a lo largo de la rampa, desde su extremo «from», la toca la partícula; al escribirla se pone ahí
inspector-inertia-presets = gira como
inspector-inertia-point = un punto
inspector-inertia-point-hint = Inercia 0: nunca gira, sin rozamiento en los choques
inspector-inertia-disc = un disco macizo
inspector-inertia-disc-hint = Inercia 0,5: I = ½ m r²; rueda por una pendiente a ⅔ g sen θ
inspector-inertia-ring = un anillo
inspector-inertia-ring-hint = Inercia 1: I = m r²; rueda por una pendiente a ½ g sen θ
link-too-long = Este enlace es demasiado largo para una escena de NewtonLab ({ $length } caracteres; el límite es { $limit }).
link-no-example = Este enlace nombra una escena incorporada que no existe: '{ $name }'.
link-not-base64 = Este enlace está dañado: su escena no es base64 válido (¿se cortó o se editó?).
link-too-large = La escena de este enlace ocupa más de { $megabytes } MB descomprimida; no se abrió.
link-not-unpacked = Este enlace está dañado: su escena no se pudo descomprimir (¿se cortó o se editó?).
link-not-text = Este enlace está dañado: su escena no es texto.
menu-share-link = Compartir enlace…
menu-share-link-hint = Un enlace que abre esta escena, con su lección, en la versión para navegador: para un correo o la página de la clase
menu-open-link = Abrir enlace…
menu-open-link-hint = Abrir la escena de un enlace de NewtonLab pegado aquí
link-share-title = Compartir enlace
link-open-title = Abrir enlace
link-address = Dirección de la versión para navegador que abre su clase:
link-address-hint = Donde se sirve la carpeta de scripts/build-web.sh (un servidor del centro, GitHub Pages); la escena viaja en el propio enlace, nunca a un servidor.
link-length = { $length } caracteres en total
link-copy = Copiar enlace
link-copied = El enlace a esta escena está en el portapapeles.
link-paste = Pegue un enlace a una escena de NewtonLab:
link-open = Abrir
link-untitled = Escena enlazada
link-not-newtonlab = Esto no es un enlace a una escena de NewtonLab: no lleva ninguna parte #scene= ni #example=.
link-scene-too-large = Esta escena es demasiado grande para un enlace ({ $length } caracteres; el límite es { $limit }): guárdela como archivo.

## The scene checker (the physics crate): problems in a scene file or a typed value
scene-the-scene = escena
scene-named = { $kind ->
        [particle] partícula
        [spring] resorte
        [rod] varilla
        [string] cuerda
        [ramp] rampa
        [body] cuerpo
        [pin] pasador
        [hinge] bisagra
        [pulley] polea
        [force] fuerza
        [series] serie
        [slider] deslizador
        [question] pregunta
       *[graph] gráfica
    } '{ $name }'
scene-numbered = { $kind ->
        [particle] partícula
        [spring] resorte
        [rod] varilla
        [string] cuerda
        [ramp] rampa
        [body] cuerpo
        [pin] pasador
        [hinge] bisagra
        [pulley] polea
        [force] fuerza
        [series] serie
        [slider] deslizador
        [question] pregunta
       *[graph] gráfica
    } #{ $number }
scene-not-finite = { $field } debe ser un número finito, no { $value }
scene-not-positive = { $field } debe ser mayor que 0, no { $value }
scene-negative = { $field } debe ser 0 o más, no { $value }
scene-not-fraction = { $field } debe estar entre 0 y 1, no { $value }
scene-too-large = { $field } { $value } es demasiado grande para simular con fiabilidad: los números de una escena son 0 o de tamaño entre 1e-100 y 1e100, para que fuerzas y energías queden dentro del rango de f64
scene-too-small = { $field } { $value } es demasiado pequeño para simular con fiabilidad: los números de una escena son 0 o de tamaño entre 1e-100 y 1e100, para que fuerzas y energías queden dentro del rango de f64
scene-vector-not-finite = { $field } debe tener componentes finitas
scene-bounds-order = bounds: min debe estar abajo a la izquierda de max, no min [{ $a }, { $b }] y max [{ $c }, { $d }]
scene-name-empty = name no debe estar vacío
scene-name-taken = el nombre '{ $name }' ya lo usa { $earlier }; los nombres deben ser únicos
scene-drag-too-strong = un rozamiento lineal de { $a } kg/s sobre { $b } kg frena la partícula en un factor e cada { $c } s, más deprisa de lo que un paso de tiempo de { $d } s puede seguir (el método crearía energía de la nada): tome un paso de tiempo de { $c } s como mucho, o dopri5
scene-drag-twice = a la vez una resistencia del aire cuadrática c ({ $a } kg/m) y un coeficiente de arrastre ({ $b }): indique uno de los dos (el coeficiente da c = ½ ρ C_d π r²)
scene-outside-bounds = position [{ $a }, { $b }] deja la partícula (radio { $c }) fuera de los límites del mundo
scene-ends-fixed = { $kind ->
        [spring] un resorte
        [rod] una varilla
       *[string] una cuerda
    } necesita una partícula móvil al menos en un extremo; ambos extremos son fijos
scene-no-particle = { $field }: no hay ninguna partícula llamada '{ $name }'
scene-ends-points = { $kind ->
        [spring] un resorte
        [rod] una varilla
       *[string] una cuerda
    } necesita una partícula al menos en un extremo; ambos extremos son puntos fijos
scene-same-particle = ambos extremos son la partícula '{ $name }'; { $kind ->
        [spring] un resorte
        [rod] una varilla
       *[string] una cuerda
    } une dos cosas distintas
scene-graph-no-particle = { $field }: '{ $text }' no nombra ninguna partícula; no hay partícula '{ $name }'
scene-graph-no-tie = { $field }: '{ $text }' no nombra ninguna varilla ni cuerda; no hay ninguna llamada '{ $name }'
scene-graph-no-link = { $field }: «{ $text }» no nombra ninguna barra, cuerda ni muelle; no hay ninguno llamado «{ $name }»
scene-graph-time-on-y = y: el tiempo va en el eje x (x = "t")
scene-follow-unknown = follow: no hay ninguna partícula '{ $name }'; seguir el nombre de una partícula, o "all"
scene-trigger-unknown = debe ser uno de { $words }, se obtuvo '{ $got }'
scene-instrument-ends = lleva de { $least } a { $most } extremos, cada uno un punto [x, y] o el nombre de una partícula; se obtuvo { $got }
scene-count-not-whole = debe ser un número entero desde 1 (qué ocurrencia), se obtuvo { $got }
scene-instrument-no-particle = { $field }: no hay ninguna partícula llamada '{ $name }' a la que siga un extremo
scene-stopwatch-stop-on-play = stop: Play puede poner en marcha el cronómetro, no pararlo
scene-stopwatch-gate-no-tape = { $field }: la barrera de luz es el segmento de la cinta métrica; ponga una cinta en [instruments]
scene-stopwatch-no-event = event: un cronómetro que arranca o para con un evento necesita el evento (bob.x crosses 0 up)
scene-stopwatch-count = { $field } debe ser un número entero desde 1
scene-quantity-of-particle = «{ $text }»: una magnitud de una partícula es una de { $keys }; la de una barra, cuerda o muelle es angle o length, y la de una barra o cuerda también tension
scene-not-a-quantity = «{ $text }» no es una magnitud: escriba t, NOMBRE.x (o .y, .vx, .vy, .speed, .ax, .ay, .kinetic_energy; turning: .angle, .spin), BARRA.angle (o .length, .tension) o una de { $keys }
quantity-no-particle = «{ $text }»: no hay ninguna partícula llamada «{ $name }» (las partículas: { $names })
quantity-no-link = «{ $text }»: no hay ninguna barra, cuerda ni muelle llamado «{ $name }» (los que hay: { $names })
quantity-no-joint = «{ $text }»: no hay ningún pasador ni bisagra llamado «{ $name }» (los que hay: { $names })
quantity-no-pulley = «{ $text }»: no hay ninguna polea llamada «{ $name }» (las que hay: { $names })
quantity-spring-tension = «{ $text }»: «{ $name }» es un muelle; se leen su ángulo y su longitud, una tensión solo de barras y cuerdas
event-malformed = «{ $text }» no es un evento: escriba MAGNITUD crosses VALOR, seguido opcionalmente de up o down (Ball.y crosses 0 down)
event-value = «{ $text }»: «{ $value }» no es un número finito que cruzar
setting-object = «{ $text }» no nombra ningún objeto de la escena: escriba OBJETO.clave (Ball.mass, Ball.velocity.angle), world.clave o simulation.clave
setting-key = «{ $text }»: no hay ningún número con ese nombre (las claves son las del archivo de escena: mass, velocity, gravity, time_step…)
setting-part = «{ $text }»: un vector se varía por una parte, .x, .y, .magnitude o .angle (grados), y un número por ninguna
vary-malformed = «{ $text }» no es un intervalo: escriba CAMPO=DESDE:HASTA:PASO (Ball.velocity.angle=10:80:5)
series-too-many-runs = { $runs } ejecuciones, más de { $most }: elija pasos más gruesos o menos valores
series-too-many-steps = una ejecución hasta { $until } s llevaría { $steps } pasos, más de { $most }: elija un paso de tiempo mayor o una ejecución más corta
series-too-much-work = sus { $runs } ejecuciones llevarían { $work } pasos de partícula en total, más de { $most } (horas de trabajo): elija menos valores, un paso de tiempo mayor o una ejecución más corta
vary-too-many = «{ $text }» tiene { $count } valores, más de un millón: elija un paso mayor
vary-empty = «{ $text }» no tiene valores: el paso no puede ser 0 y debe ir de DESDE hacia HASTA
measure-malformed = «{ $text }» no es una medida: escriba MAGNITUD at EVENTO [#N], t at EVENTO, max MAGNITUD, min MAGNITUD, period MAGNITUD o MAGNITUD at T
measure-instant = el instante { $instant } s está fuera de la ejecución, de { $from } s a { $until } s
measure-no-period = menos de tres máximos ({ $count }) hasta { $until } s: sin periodo (se comparan al menos dos ciclos)
measure-irregular-period = sus { $count } máximos hasta { $until } s no se repiten en ningún ciclo regular: no se puede dar un periodo
measure-no-event = «{ $event }» ocurrió { $count } veces hasta { $until } s, no { $nth }
measure-none = nada medido hasta { $until } s
theory-unreadable = «{ $text }» no es una expresión: escriba aritmética de x (el valor variado) y las constantes de la escena, como v0^2*sin(2*a)/g
theory-unknown-name = una teoría puede nombrar { $names }; no «{ $name }»
scene-series-until = until debe ser un número posterior al inicio de la escena; se obtuvo { $until }
sweep-every-run-failed = todas las ejecuciones de la serie fallaron (los motivos están arriba)
sweep-run-failed = ejecución { $run }: { $why }
sweep-no-measure = ejecución { $run }: «{ $measure }»: { $why }
scene-unsatisfiable = la longitud { $length } m no se puede mantener junto con las demás varillas y cuerdas unidas a sus extremos (la disposición más cercana falla por { $miss } m); cambie una longitud o un extremo
scene-at-line-column = línea { $line }, columna { $column }
scene-at-line = línea { $line }
scene-problems-found = { $source }: { $count ->
        [1] 1 problema encontrado
       *[other] { $count } problemas encontrados
    }:
scene-got-bool = verdadero o falso
scene-got-number = un número
scene-got-text = texto
scene-got-list = una lista
scene-got-table = una tabla
scene-got-date = una fecha
scene-bad-toml = esto no es TOML válido: { $error }
scene-bad-json = esto no es JSON válido: { $error }
scene-not-a-table = { $label } debe ser una tabla, no { $got }
scene-keys-here = las claves aquí son { $keys }
scene-did-you-mean = ¿quería decir '{ $key }'?
scene-unknown-key = { $label }: clave desconocida '{ $key }'; { $hint }
scene-required = { $label }: { $key } es obligatorio
scene-the-whole = la escena
scene-version-unsupported = escena: la versión { $version } no es compatible; este NewtonLab lee la versión { $supported }
scene-version-required = escena: version es obligatorio; escriba `version = 1` al principio del archivo
scene-not-a-list = escena: '{ $key }' debe ser una lista de tablas [[{ $key }]], no { $got }
scene-must-be-finite = debe ser un número finito, no { $got }
scene-must-be-number = debe ser un número, no { $got }
scene-must-be-bool = debe ser true o false, no { $got }
scene-must-be-text = debe ser texto entre comillas, no { $got }
scene-must-be-quantities = debe ser una lista de magnitudes entre comillas, como ["A.x", "total_energy"], no { $got }
scene-vector-length = debe ser { $cartesian } o { $polar }, no una lista de { $count } números
scene-vector-extra = debe ser { $cartesian } o { $polar }; '{ $key }' no es parte de un vector
scene-vector-polar = debe ser { $cartesian } o { $polar }; un vector polar necesita magnitude y angle
scene-vector-got = debe ser { $cartesian } o { $polar }, no { $got }
scene-bounds-got = debe ser { $form }, no { $got }
scene-bounds-extra = debe ser { $form }; '{ $key }' no es parte de bounds
scene-bounds-both = debe ser { $form }; se necesitan min y max
scene-endpoint-point = debe ser el nombre de una partícula o un punto; como punto { $reason }
scene-endpoint-got = debe ser el nombre de una partícula o un punto [x, y], no { $got }
scene-not-integrator = '{ $name }' no es un integrador; elija uno de { $names }
scene-not-pair-forces = '{ $name }' no es una forma de sumar fuerzas entre pares; elija direct o tree
scene-not-colour = debe ser un color como "#d94f4f", no "{ $text }"

## The command line
run-non-finite = en t = { $time } s la partícula '{ $particle }' alcanzó una posición o velocidad no finita (dos cuerpos se acercaron demasiado, o el paso de tiempo es demasiado grande para las fuerzas)
run-value-not-finite = en t = { $time } s { $quantity } es { $value }, no un número que quepa en una fila: dos cuerpos están tan cerca que la fuerza entre ellos desborda
run-step-too-small = en t = { $time } s el integrador adaptativo necesitó un paso demasiado pequeño para avanzar con la tolerancia { $tolerance }; afloje la tolerancia o compruebe si hay cuerpos que se atraviesan
run-too-many-steps = en t = { $time } s llegar a { $target } s llevó más de { $limit } pasos adaptativos (el paso de tiempo de { $step } s es demasiado largo para el movimiento de esta escena); elija un time_step menor
cli-no-window = la app no pudo abrir una ventana: { $error }
    (los comandos sin ventana funcionan igual: vea `newtonlab --help`)
cli-check-ok = { $source }: correcto ({ $particles } partículas, { $springs } resortes, { $ramps } rampas, integrador { $integrator }, paso de tiempo { $step } s)
cli-check-tree = nota: la gravitación se suma con el árbol de Barnes–Hut (ángulo de apertura { $angle })
cli-check-tree-and-charges = nota: la gravitación se suma con el árbol de Barnes–Hut (ángulo de apertura { $angle }); las fuerzas de Coulomb entre sus { $charged } partículas cargadas se suman directamente, par a par
cli-until-not-finite = --until debe ser un número finito de segundos, no { $until }
cli-every-invalid = --every debe ser un número finito de segundos mayor que 0, no { $every }
cli-event-invalid = --events: { $reason }
cli-column-invalid = --column: { $reason }
cli-until-negative = --until debe ser 0 o más segundos, no { $until }
cli-until-before-start = --until { $until } es anterior al start_time { $start } s de la escena; una ejecución avanza desde su inicio
cli-too-many-rows = --until { $until } con --every { $every } escribiría { $rows } filas de { $columns } números, más de { $most } números; elija un --every mayor, o indique --no-limit
cli-too-many-steps = --until { $until } con un paso de tiempo de { $step } s llevaría { $steps } pasos, más de { $most }; elija un time_step mayor o un --until más corto, o indique --no-limit
cli-cannot-create = no se puede crear el archivo de salida '{ $path }': { $error }
cli-cannot-write-csv = no se puede escribir el CSV: { $error }
cli-cannot-save-state = no se puede escribir el estado en '{ $path }': { $error }
cli-sampling-note = nota: --every { $every } s no es un número entero de pasos de tiempo ({ $step } s): cada muestra acorta un paso para caer sobre ella, así que esta ejecución integra con un paso efectivo menor que el de la escena y sus números difieren un poco de una ejecución muestreada en un múltiplo de { $step } s
cli-cannot-create-log = no se puede crear el registro de choques '{ $path }': { $error }
cli-no-example = no hay ninguna escena incorporada '{ $name }'; los ejemplos son: { $names }
cli-cannot-read = no se puede leer el archivo de escena '{ $source }': { $error }

## The inspector's fields (English: the field table's words, physics::fields; the file's keys stay as they are)
field-world-gravity = gravedad
field-world-gravity-help = El campo uniforme
field-world-gravitation = gravitación entre partículas
field-world-gravitation-help = La atracción de Newton, inversa al cuadrado de la distancia, entre cada par
field-world-gravitational-constant = G
field-world-gravitational-constant-help = La constante gravitatoria (el valor del artículo)
field-world-electrostatics = electrostática
field-world-electrostatics-help = La ley de Coulomb entre partículas cargadas
field-world-coulomb-constant = k
field-world-coulomb-constant-help = La constante de Coulomb
field-world-softening = suavizado
field-world-softening-help = Longitud de suavizado de Plummer ε de la gravitación y de Coulomb: fuerza ∝ r/(r² + ε²)^(3/2), finita en pasos cercanos
field-world-air-density = densidad del aire
field-world-air-density-help = ρ, contra la que empuja el coeficiente de arrastre de una partícula: ½ ρ C_d π r² v² (aire a 20 °C: 1,2)
field-world-magnetic-field = campo magnético
field-world-magnetic-field-help = B_z, saliendo de la pantalla positivo: una fuerza q v × B sobre cada partícula cargada en movimiento
field-world-collisions = choques entre partículas
field-world-collisions-help = Las partículas chocan y se apoyan unas en otras; false: se atraviesan (las rampas y los límites las siguen deteniendo)
field-world-restitution = restitución
field-world-restitution-help = Choques entre partículas: 0 (pegajoso) a 1 (elástico)
field-world-friction = rozamiento entre partículas
field-world-friction-help = μ entre partículas que giran en los choques: sus puntos de contacto se agarran hasta μ veces el impulso normal
field-world-bounds = límites
field-world-bounds-help = Una caja reflectante alrededor del mundo
field-simulation-integrator = integrador
field-simulation-integrator-help = Cómo se integra el movimiento en el tiempo: euler, semi-implicit-euler, verlet, rk4, pefrl, dopri5
field-simulation-time-step = paso de tiempo
field-simulation-time-step-help = El paso (dopri5: el paso más grande)
field-simulation-tolerance = tolerancia
field-simulation-tolerance-help = Solo dopri5: error permitido por paso, relativo y absoluto
field-simulation-time-scale = escala de tiempo
field-simulation-time-scale-help = Segundos simulados por segundo real al reproducir en la app
field-simulation-pair-forces = fuerzas entre pares
field-simulation-pair-forces-help = Cómo se suma la gravitación: direct (cada par, exacto) o tree (Barnes–Hut, para miles de cuerpos)
field-simulation-opening-angle = ángulo de apertura
field-simulation-opening-angle-help = Solo tree: un grupo de tamaño s a distancia d actúa como un cuerpo cuando s/d es menor que esto
field-simulation-start-time = tiempo inicial
field-simulation-start-time-help = El instante que describe el estado de la escena (un estado guardado conserva su tiempo)
field-particle-mass = masa
field-particle-mass-help = Masa, mayor que 0
field-particle-radius = radio
field-particle-radius-help = Radio, mayor que 0
field-particle-charge = carga
field-particle-charge-help = Carga eléctrica
field-particle-position = posición
field-particle-position-help = Posición
field-particle-velocity = velocidad
field-particle-velocity-help = Velocidad
field-particle-acceleration = aceleración
field-particle-acceleration-help = Una aceleración constante añadida a todas las fuerzas
field-particle-fixed = fija
field-particle-fixed-help = Una partícula fija nunca se mueve; aun así atrae, repele y recibe choques
field-particle-linear-drag = resistencia del aire, lineal
field-particle-linear-drag-help = Resistencia del aire b: una fuerza b v contra el movimiento (movimiento lento en un fluido espeso)
field-particle-quadratic-drag = resistencia del aire, cuadrática
field-particle-quadratic-drag-help = Resistencia del aire c: una fuerza c v² contra el movimiento (una pelota en el aire: c = ½ ρ C_d A)
field-particle-drag-coefficient = coeficiente de arrastre
field-particle-drag-coefficient-help = C_d: resistencia del aire ½ ρ C_d π r² v² a partir de la densidad del aire del mundo y del radio (una pelota: 0,47); en lugar de la c cuadrática
field-particle-inertia = momento de inercia
field-particle-inertia-help = I/(m r²): 0 un punto que nunca gira, 0,5 un disco macizo, 1 un anillo fino
field-particle-spin = giro
field-particle-spin-help = Velocidad angular ω, positiva en sentido antihorario (de una partícula que gira)
field-particle-angle = ángulo
field-particle-angle-help = Orientación, en sentido antihorario: hacia dónde apunta el radio marcado de la partícula que gira
field-particle-color = color
field-particle-color-help = Color de dibujo, "#rrggbb"
field-spring-from = desde
field-spring-from-help = El nombre de una partícula, o un punto fijo [x, y]
field-spring-to = hasta
field-spring-to-help = El nombre de una partícula, o un punto fijo [x, y]
field-spring-stiffness = rigidez
field-spring-stiffness-help = k, 0 o más
field-spring-natural-length = longitud natural
field-spring-natural-length-help = La longitud a la que el resorte no ejerce fuerza
field-spring-damping = amortiguamiento
field-spring-damping-help = b: fuerza −b·(velocidad relativa a lo largo del resorte)
field-rod-from = desde
field-rod-from-help = El nombre de una partícula, o un punto fijo [x, y]
field-rod-to = hasta
field-rod-to-help = El nombre de una partícula, o un punto fijo [x, y]
field-rod-length = longitud
field-rod-length-help = La distancia que la varilla mantiene entre sus extremos
field-string-from = desde
field-string-from-help = El nombre de una partícula, o un punto fijo [x, y]
field-string-to = hasta
field-string-to-help = El nombre de una partícula, o un punto fijo [x, y]
field-string-length = longitud
field-string-length-help = Lo más que la cuerda deja separarse a sus extremos
field-string-restitution = restitución
field-string-restitution-help = Cuando se tensa de golpe: 0 (los extremos dejan de separarse) a 1 (rebotan)
field-ramp-from = desde
field-ramp-from-help = Un extremo de la rampa
field-ramp-to = hasta
field-ramp-to-help = El otro extremo
field-ramp-thickness = grosor
field-ramp-thickness-help = La rampa es todo punto a menos de la mitad de esto de su segmento
field-ramp-restitution = restitución
field-ramp-restitution-help = 0 (sin rebote) a 1 (perfectamente elástico)
field-ramp-friction = rozamiento
field-ramp-friction-help = Coeficiente de rozamiento estático y cinético
inspector-name = nombre
inspector-name-hint = Único entre todos los objetos
inspector-rod-length-differs = Sus extremos están a { $distance } m al empezar, no a { $length } m: la barra los lleva a su longitud antes del primer paso.
inspector-string-too-short = Sus extremos están a { $distance } m al empezar, más que sus { $length } m: la cuerda los lleva a su longitud antes del primer paso.
inspector-bounds-min-hint = La esquina inferior izquierda de la caja
inspector-bounds-max-hint = La esquina superior derecha de la caja
inspector-fixed-point = punto fijo
inspector-end-hint = Una partícula, o un punto fijo del mundo
inspector-end-point = { $end }: punto
inspector-end-point-hint = El punto fijo, metros

## Graphs, the status line, edits (Undo and Redo), file errors
notice-no-example = no hay ningún ejemplo '{ $name }'
notice-cannot-read-in-browser = no se puede leer '{ $path }' en el navegador
status-frame-time = fotograma { $ms } ms
status-objects = { $particles } partículas, { $springs } resortes, { $ties } varillas y cuerdas, { $ramps } rampas
edit-set = cambiar { $what }
edit-add-graph = añadir gráfica
edit-remove-graph = quitar gráfica
edit-add-series = añadir serie
edit-remove-series = quitar serie
edit-set-x-axis = cambiar el eje x
edit-paste = pegar
edit-move-group = mover selección
edit-delete-group = eliminar selección
edit-set-time-scale = cambiar la escala de tiempo
edit-set-integrator = cambiar el integrador
edit-set-time-step = cambiar el paso de tiempo
edit-edit-from-here = editar desde aquí
edit-move-particle = mover partícula
edit-move-ramp = mover rampa
edit-move-ramp-end = mover extremo de rampa
edit-set-velocity = cambiar la velocidad
edit-add-particle = añadir partícula
edit-add-spring = añadir resorte
edit-add-rod = añadir varilla
edit-add-string = añadir cuerda
edit-add-ramp = añadir rampa
edit-rename = renombrar
edit-delete-particle = eliminar partícula
edit-delete-spring = eliminar resorte
edit-delete-rod = eliminar varilla
edit-delete-string = eliminar cuerda
edit-delete-ramp = eliminar rampa
graph-untitled = Gráfica { $number }
graph-figure-title = { $y } frente a { $x }
graph-particle = partícula
graph-particle-hint = La partícula cuya magnitud añadir
graph-quantity = magnitud
graph-quantity-hint = La magnitud que añadir
graph-tension-hint = Dibujar la fuerza que transmite esta varilla o cuerda (la tracción es positiva)
graph-marks = extremos y ceros
graph-marks-hint = Marcar los máximos, mínimos y cruces por cero de cada serie, localizados en la ejecución cuando se detiene (como los eventos del cronómetro; leídos de las muestras mientras corre y en escenas muy grandes), y dar el periodo entre máximos sucesivos
graph-earlier-runs = simulaciones anteriores
graph-forget-earlier = olvidar simulaciones anteriores
graph-forget-earlier-hint = Las curvas grises son las simulaciones anteriores a la última (hasta tres, guardadas de una reproducción a otra); olvidarlas
graph-fit = ajuste
graph-fit-hint = Ajustar cada serie a un modelo por mínimos cuadrados: sus parámetros con sus incertidumbres típicas, y la curva a trazos
graph-fit-none = ninguno
graph-fit-line = recta a + b x
graph-fit-parabola = parábola a + b x + c x²
graph-fit-sine = seno A sin(ω x + φ) + c
graph-fit-decay = decaimiento A e^(−x/τ) + c
graph-fit-result = { $quantity }, { $model }: { $parameters } (residuo cuadrático medio { $rms })
graph-reset-view = restablecer vista
graph-reset-view-hint = Volver a mostrar toda la simulación (Ctrl y la rueda hacen zoom, arrastrar desplaza)
graph-period = periodo de { $quantity }: { $period } s (media de { $cycles } { $cycles ->
    [one] ciclo
   *[other] ciclos
} de { $maxima } { $maxima ->
    [one] máximo
   *[other] máximos
}, { $how ->
    [located] localizados en la ejecución
   *[sampled] leídos de las muestras
})
graph-period-too-few = periodo de { $quantity }: aún no ({ $count } máximos; un tercero dice si se repiten)
graph-period-irregular = periodo de { $quantity }: no se puede dar (sus { $count } máximos no se repiten en ningún ciclo regular)
graph-angle-hint = Representar el ángulo de esta barra, cuerda o muelle respecto a la vertical hacia abajo (positivo en sentido antihorario)
graph-length-hint = Representar la distancia entre los extremos de esta barra, cuerda o muelle
graph-total-hint = Dibujar esta magnitud del sistema
graph-x-axis-now = eje x: { $quantity }
graph-remove-series-hint = Quitar esta serie
impacts-go-to-hint = Mostrar la ejecución en este choque
units-comes-to = da { $value }
units-empty = está vacío
units-brackets = sus paréntesis no casan
units-ends-with-operator = termina con un operador
units-unknown-word = «{ $word }» no es una función, constante ni unidad de este campo
units-unreadable = no se puede leer como una operación
expression-too-long = una expresión de { $length } caracteres es más larga que cualquier fórmula que NewtonLab lee (como mucho { $most })
expression-too-deep = una expresión con paréntesis a { $depth } niveles es más profunda que cualquier fórmula que NewtonLab lee (como mucho { $most })
units-not-a-number = «{ $text }» no es un número: { $reason }; escriba un número o una operación como 2*pi o sqrt(2)/2
units-not-a-number-unit = «{ $text }» no es un número: { $reason }; escriba un número o una operación como 2*pi o sqrt(2)/2, con una unidad como { $units }
file-cannot-read = no se puede leer '{ $path }': { $error }
file-cannot-write = no se puede escribir '{ $path }': { $error }
file-cannot-read-file = no se puede leer '{ $path }'
file-cannot-download = el navegador no pudo descargar '{ $path }'
file-cannot-autosave = no se puede guardar automáticamente en '{ $path }': { $error }
file-cannot-encode = no se pudo codificar la imagen: { $error }
reading-full = { $value } (el valor completo: haz clic para copiarlo)
reading-copied = { $value } copiado al portapapeles.
experiments-heading = Series de experimentos
experiments-heading-hint = Variar un valor de la escena, ejecutarla una vez por valor y representar lo que midió cada ejecución, con la ley esperada
experiment-add = Añadir una serie de experimentos
experiment-add-hint = Una serie para la partícula seleccionada (o la primera): su ángulo de lanzamiento de 15° a 75°, midiendo su punto más alto; cualquier campo se puede cambiar
experiment-none = No existe esa serie de experimentos.
experiment-title = Serie { $number }
experiment-figure-title = { $measure } frente a { $vary }
experiment-remove = quitar
experiment-remove-hint = Quitar esta serie de la escena
experiment-vary = variar
experiment-vary-hint = El valor variado, como lo nombra el archivo de escena: Ball.velocity.angle, Bob.mass, world.gravity.y, simulation.time_step
experiment-from = desde
experiment-from-hint = El primer valor
experiment-to = hasta
experiment-to-hint = El último valor (alcanzado cuando los pasos llegan a él)
experiment-step = paso
experiment-step-hint = El paso entre valores
experiment-until = hasta t (s)
experiment-until-hint = Cuánto dura cada ejecución, segundos de tiempo simulado
experiment-measure = medida
experiment-measure-hint = Lo que se mide en cada ejecución, separado por ";": Ball.x at Ball.y crosses 0 down, t at Bob.vx crosses 0 #3, max Ball.y, min Ball.vy, period Bob.x, Ball.x at 1.5
experiment-theory = teoría
experiment-theory-hint = Opcional: la ley de la primera medida, en x (o a: el valor variado, un ángulo en radianes) y las constantes de la escena g, m, r, v0, h, b, c (las de la partícula variada), L, k. v0^2*sin(2*a)/g es el alcance de un proyectil
experiment-run = Ejecutar la serie
experiment-run-hint = Ejecutar la escena una vez por valor (en todos los núcleos) y representar las medidas
experiment-progress = { $done } de { $total } ejecuciones
experiment-took = { $runs } ejecuciones en { $seconds } s
experiment-export-csv-hint = Los resultados en CSV: el valor variado y luego cada medida (como los escribe newtonlab sweep)
experiment-residuals = { $measure } − teoría: como mucho { $worst }
experiment-residual = medido − teoría
experiment-theory-curve = teoría: { $law }
edit-add-experiment = añadir serie de experimentos
edit-change-experiment = cambiar serie de experimentos
edit-remove-experiment = quitar serie de experimentos
experiment-choose = elegir…
experiment-choose-hint = Elegir el valor a variar entre los de la partícula seleccionada (o la primera) y los del mundo
experiment-add-measure = añadir una medida…
experiment-add-measure-hint = Añadir una medida frecuente, para la partícula seleccionada (o la primera) y cada barra o cuerda; se edita en el campo
scene-clock-too-coarse = el paso de tiempo { $step } s es demasiado fino para un reloj en { $start } s: un instante allí se redondea en más de 1e-4 de un paso (elija un paso de al menos una billonésima del tiempo inicial, o empiece más cerca de 0)
scene-same-point = empieza en el mismo punto que la partícula «{ $other }», donde la fuerza entre ellas es infinita: mueva una, o dé a [world] un suavizado (softening)
cli-every-too-fine = --every { $every } es demasiado fino para instantes hasta { $until } s: los tiempos de las filas k × every se confundirían (elija un --every mayor)
cli-state-not-saveable = el estado en { $time } s no se puede guardar como una escena que vuelva a abrirse: { $problem }
total-kinetic-energy = energía cinética
total-potential-energy = energía potencial
total-total-energy = energía total
total-momentum-x = momento x
total-momentum-y = momento y
total-angular-momentum = momento angular
cli-not-a-file = «{ $source }» no es un archivo (un directorio, un dispositivo o una tubería): indique un archivo de escena, o example:NAME
cli-file-too-large = «{ $source }» ocupa { $megabytes } MB: un archivo de escena puede ocupar como mucho { $most } MB
cli-same-output = { $first } y { $second } nombran ambos «{ $path }»: sus filas se mezclarían; dé a cada uno su propio archivo
scene-inside-ramp = empieza con su centro dentro de la rampa «{ $ramp }»: colóquela fuera de la rampa (sobre ella, se queda apoyada)
cli-too-much-work = --until { $until } llevaría { $steps } pasos de { $particles } partículas móviles, { $work } pasos-partícula, más de { $most } (de minutos a horas de trabajo); elija un time_step mayor, un --until más corto o menos partículas, o indique --no-limit
run-tie-not-held = en t = { $time } s la varilla o cuerda «{ $tie }» no pudo mantenerse en su longitud: las fuerzas sobre ella son demasiado fuertes para el paso de tiempo, las masas de sus extremos demasiado desiguales, o su longitud no es compatible con las de las demás; elija un time_step menor o revise longitudes y masas
run-pulley-reached = en t = { $time } s el cuerpo «{ $body }» llegó a la rueda de la polea «{ $pulley }»: su lado de la cuerda se acabó (detén la simulación antes o cuelga el cuerpo más abajo)
run-tie-too-far = en t = { $time } s la varilla o cuerda «{ $tie }» está demasiado lejos del origen para su longitud de { $length } m: el solo redondeo de las posiciones de sus extremos impide mantenerla a una milmillonésima de su longitud; acerque la escena al origen o alargue el enlace
run-drag-too-strong = en t = { $time } s la resistencia del aire sobre la partícula «{ $particle }» la frena en un factor e cada { $decay } s, más deprisa de lo que un paso de tiempo de { $step } s puede seguir (el método crearía energía de la nada); elija un time_step de ese valor como mucho, o dopri5
run-left-bounds = en t = { $time } s la partícula «{ $particle }» salió de los límites del mundo a { $speed } m/s, demasiado rápido para que el paso de tiempo resuelva sus choques con las paredes; elija un time_step menor
scene-got-null = null
scene-json-duplicate-key = la clave «{ $key }» aparece dos veces en un objeto; deje una
scene-number-beyond-f64 = { $text } está fuera de lo que cabe en un número de 64 bits (de unos 2,2e-308 a 1,8e308 en tamaño, o 0)
file-save-changes = Guardar
file-save-changes-hint = Guardar los cambios y seguir
scene-body-shape = shape debe ser "box" o "polygon", no "{ $got }"
scene-must-be-points = debe ser una lista de puntos, como [[0.0, 0.0], [0.4, 0.0], [0.2, 0.3]], no { $got }
scene-body-box-size = una caja necesita { $field } mayor que 0
scene-body-not-box = { $field } es de una caja: el contorno de un polígono son sus vértices (quite { $field })
scene-body-vertex-count = un polígono necesita de 3 a { $most } vértices, no { $count }
scene-body-vertex-not-finite = el vértice { $k } no es un punto finito de un tamaño que NewtonLab simula (como mucho 1e100)
scene-body-repeated-vertex = los vértices { $a } y { $b } son el mismo punto: quite uno
scene-body-collinear = los vértices { $a }, { $b } y { $c } están en una recta: quite el del medio
scene-body-clockwise = los vértices van en sentido horario: escríbalos en sentido antihorario (invierta la lista)
scene-body-concave = el contorno no es convexo en el vértice { $k }: un cuerpo debe ser convexo (construya una forma cóncava con varios cuerpos)
scene-body-winds = el contorno se cruza a sí mismo (da más de una vuelta): escriba las esquinas en orden alrededor del contorno
scene-body-no-mass = necesita una masa (kg) o una densidad (kg/m²)
scene-body-mass-and-density = dé una masa o una densidad, no ambas
scene-body-static-friction = static_friction { $static } debe ser al menos el rozamiento cinético { $kinetic }
scene-body-overlap = se solapa con el cuerpo «{ $other }» al comenzar: separe uno de ellos
scene-motor = motor debe ser {"{"} torque = N·m {"}"} o {"{"} spin = rad/s, max_torque = N·m {"}"}
scene-joint-no-body = no hay ningún cuerpo «{ $name }» (pasadores, bisagras y poleas sujetan cuerpos, [[body]])
scene-joint-particle = «{ $name }» es una partícula: pasadores, bisagras y poleas sujetan cuerpos ([[body]]), aún no partículas; une partículas con una varilla o una cuerda
scene-hinge-itself = una bisagra une dos cuerpos, pero a y b son ambos «{ $body }»
scene-joint-twice = sujeta los mismos cuerpos en el mismo punto que «{ $other }»: quita uno
scene-joint-fixed = no sujeta nada que pueda moverse: todos sus cuerpos son fijos
scene-joint-anchor = { $field } no está en el punto de la articulación at: omítelo y se calcula a partir de at
scene-pulley-same = la cuerda de una polea une dos cuerpos, pero a y b son ambos «{ $body }»
scene-pulley-inside = el cuerpo «{ $body }» está en la rueda: debe colgar separado de la rueda de la polea
scene-force-unreadable = '{ $text }' no es una expresión: escriba una de x, y, vx, vy, t, m, q con números, + − * / ^, sqrt, sin, cos, exp, … (por ejemplo -2*x - 0.5*x^3)
scene-force-unknown-name = nombra '{ $name }': una fuerza puede nombrar { $names }
scene-force-potential-name = nombra '{ $name }': una energía potencial depende solo de la posición y puede nombrar { $names }
scene-force-on-body = '{ $name }' es un cuerpo: las fuerzas propias actúan sobre partículas
scene-force-on-nothing = no hay ninguna partícula '{ $name }'
scene-force-not-finite = sobre la partícula '{ $particle }' la fuerza donde empieza es ({ $x }, { $y }) N, no una fuerza finita
scene-force-potential-of-motion = una energía potencial corresponde a una fuerza que depende solo de la posición, y esta fuerza nombra la velocidad o el tiempo: omita el potencial
scene-force-potential-mismatch = donde empieza la partícula '{ $particle }' el −∇U del potencial es ({ $ux }, { $uy }) N pero la fuerza es ({ $fx }, { $fy }) N: el balance de energía no cerraría; dé el potencial de esta fuerza, o ninguno
scene-limits = limits debe ser [inferior, superior] en grados
scene-limits-order = limits deben ser finitos con el inferior por debajo del superior, no [{ $lower }, { $upper }]
scene-limits-start = el ángulo de la articulación al comenzar, { $angle }°, está fuera de sus limits
cli-check-body = cuerpo «{ $name }»: { $shape }, área { $area } m², masa { $mass } kg, momento de inercia { $inertia } kg·m² respecto a su centroide, en { $centroid } m del contorno tal como se escribió
cli-check-pin = pasador «{ $name }»: sujeta el cuerpo «{ $body }» en { $at } m; su momento de inercia respecto al pasador es { $inertia } kg·m²
cli-check-hinge = bisagra «{ $name }»: une el cuerpo «{ $b }» al cuerpo «{ $a }» en { $at } m
cli-check-pulley = polea «{ $name }»: una cuerda del cuerpo «{ $a }» sobre una rueda de radio { $radius } m y { $mass } kg en { $at } m al cuerpo «{ $b }»
cli-check-force = fuerza '{ $name }': ({ $fx }, { $fy }) N sobre { $on }; sin potencial, el residuo del balance contiene su trabajo
cli-check-force-potential = fuerza '{ $name }': ({ $fx }, { $fy }) N sobre { $on }, con su energía potencial
cli-check-force-everything = cada partícula
cli-check-magnetic = campo magnético B_z = { $field } T sobre { $charged } partículas cargadas (q v × B: las desvía y no realiza trabajo)
cli-check-joints-start = las velocidades de los cuerpos al comenzar separan sus articulaciones: la simulación empieza con las velocidades más cercanas que las articulaciones permiten, { $lost } J menos de energía cinética
cli-check-motor-torque = , movido por un motor de { $torque } N·m
cli-check-motor-spin = , movido por un motor a { $spin } rad/s con { $torque } N·m como máximo
cli-check-bodies-free = los cuerpos chocan con paredes, rampas y entre sí, se apoyan y deslizan sobre ellos (entre dos cuerpos, la menor restitución y la media geométrica de los rozamientos); los cuerpos con pasador o bisagra aún no se encuentran con nada; aún no se encuentran con partículas, y resortes, varillas y cuerdas no se les unen
edit-move-body = mover cuerpo
edit-add-body = añadir cuerpo
edit-delete-body = eliminar cuerpo
edit-add-pin = añadir pasador
edit-delete-pin = eliminar pasador
edit-add-hinge = añadir bisagra
edit-delete-hinge = eliminar bisagra
edit-add-pulley = añadir polea
edit-delete-pulley = eliminar polea
edit-add-force = añadir fuerza
edit-delete-force = eliminar fuerza
tool-box = Caja
tool-box-hint = Arrastrar de esquina a esquina para dibujar una caja rígida (7)
field-body-width = ancho
field-body-width-help = Extensión de una caja a lo largo de su propio eje x
field-body-height = alto
field-body-height-help = Extensión de una caja a lo largo de su propio eje y
field-body-mass = masa
field-body-mass-help = Masa, mayor que 0 (o dé la densidad en su lugar)
field-body-density = densidad
field-body-density-help = Masa por área: el área de la forma da la masa
field-body-position = posición
field-body-position-help = El centroide
field-body-angle = ángulo
field-body-angle-help = Orientación, en sentido antihorario
field-body-velocity = velocidad
field-body-velocity-help = La velocidad del centroide
field-body-spin = giro
field-body-spin-help = Velocidad angular ω, positiva en sentido antihorario
field-body-restitution = restitución
field-body-restitution-help = 0 (sin rebote) a 1 (perfectamente elástico)
field-body-friction = rozamiento
field-body-friction-help = Coeficiente de rozamiento cinético
field-body-fixed = fijo
field-body-fixed-help = Un cuerpo fijo nunca se mueve
field-body-color = color
field-body-color-help = Color de dibujo, "#rrggbb"
status-bodies = { $bodies } cuerpos
tool-polygon = Polígono
tool-polygon-hint = Hacer clic en las esquinas de un polígono convexo rígido; clic de nuevo en la primera para cerrarlo (8)
lesson-no-title = una lección necesita un título
lesson-text-too-long = el texto ocupa { $size } KiB; el texto de una lección puede ocupar como mucho { $most } KiB (una imagen va junto a la escena, no dentro)
lesson-html = el texto contiene HTML (una etiqueta como <script> o <img>), que una lección nunca muestra ni ejecuta: escriba Markdown y, en una fórmula, deje un espacio tras <
lesson-bad-id = el id '{ $id }' debe tener solo letras, cifras, _ o - (es lo que nombra una respuesta: ID=VALOR)
lesson-repeated-id = el id '{ $id }' ya lo usa una pregunta anterior
lesson-no-prompt = una pregunta necesita un enunciado
lesson-unit-misfit = la unidad '{ $unit }' no encaja con la medida, que está en { $si }
lesson-tolerance = tolerance debe ser mayor que 0, pero es { $tolerance }
lesson-slider-range = min { $min } debe ser menor que max { $max }
lesson-slider-step = step debe ser mayor que 0 y como mucho max − min, pero es { $step }
lesson-slider-rule = con { $value } la escena incumple una regla: { $why }
cli-check-lesson = lección '{ $title }': { $sliders } deslizador(es), { $questions } pregunta(s)
cli-lesson-none = { $source } no tiene [lesson]: indique un archivo de escena con una lección, o una lección de ejemplo (newtonlab examples)
cli-lesson-answer-malformed = --answer '{ $text }' debe ser ID=VALOR, como { $first }="1.5 s"; los ids: { $ids }
cli-lesson-unknown-id = --answer '{ $text }': la lección no tiene ninguna pregunta con ese id; sus { $count } pregunta(s): { $ids }
cli-lesson-answer-unreadable = --answer para '{ $id }' debe ser una magnitud en { $unit } (u otra unidad de su tipo): { $why }
cli-lesson-unmeasured = la simulación no puede responder la pregunta '{ $id }': { $why }
menu-lesson = Lección
menu-lesson-hint = Mostrar u ocultar la lección: sus instrucciones, deslizadores y preguntas
key-lesson = Mostrar u ocultar la lección
edit-slide = mover un deslizador de la lección
inspector-about = Acerca de esta escena
lesson-sliders = Pruebe a cambiar
lesson-sliders-reset = Reinicie la ejecución para cambiarlos
lesson-questions = Preguntas
lesson-answer-hint = su respuesta, en { $unit }
lesson-check = Comprobar
lesson-right = Correcto
lesson-close = Cerca — revise su medida
lesson-not-yet = Todavía no — mida otra vez
lesson-revealed = La simulación mide { $value }.
worksheet-no-lesson = la escena no tiene lección: una hoja de trabajo es de una lección ([lesson] en el archivo de escena)
worksheet-no-font = no se pudo leer la fuente incluida para la hoja de trabajo
worksheet-no-picture = la imagen de la escena no tiene tamaño
worksheet-failed = no se pudo escribir la hoja de trabajo: { $why }
worksheet-name = Nombre:
worksheet-sliders = Puede cambiar
worksheet-slider = { $field }: de { $min } a { $max }{ $unit }, en pasos de { $step }
worksheet-key-title = Soluciones: { $title }
worksheet-key-line = { $id }: { $value } { $unit } (correcto dentro de ± { $tolerance }, cerca dentro de ± { $close })
worksheet-key-none = { $id }: la simulación no da ningún valor: { $why }
menu-worksheet = Exportar hoja de trabajo…
menu-worksheet-hint = La lección como hoja de trabajo para imprimir (PDF): sus instrucciones, una imagen de la escena y sus preguntas con líneas para las respuestas
menu-answer-key = Exportar hoja de trabajo con soluciones…
menu-answer-key-hint = La hoja de trabajo y, en una página aparte, el valor de la simulación para cada pregunta (PDF)
file-title-pdf = Exportar la hoja de trabajo (PDF)
notice-worksheet-saved = Hoja de trabajo guardada en { $path }
menu-fields = Campos y fuerzas
menu-bodies = Cuerpos rígidos
menu-lessons = Lecciones
