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
menu-save-canvas-hint = Una imagen del lienzo tal como se ve
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
key-play-pause = Reproducir o pausar
key-step = Un paso adelante
key-step-back = Un paso atrás en la ejecución
key-reset = Volver a la escena construida
key-fit = Ajustar la vista a la escena
key-stopwatch = Cronómetro
key-inspector = Mostrar u ocultar el inspector
key-graphs = Mostrar u ocultar las gráficas
key-projector = Modo proyector
key-help = Esta lista de teclas
canvas-key-focus = Dar el teclado al lienzo
canvas-key-cycle = Seleccionar el objeto siguiente / anterior
canvas-key-move = Mover la partícula o la rampa seleccionada un paso de la cuadrícula
canvas-key-fine = Moverla una décima de paso
canvas-key-enter = Añadir un objeto de la herramienta actual en el centro de la vista (un resorte, una varilla o una cuerda desde la partícula seleccionada)
canvas-key-escape = Devolver el teclado; Tab pasa entonces al control siguiente
canvas-key-instrument-enter = Con la cinta (M) o el transportador (A): tenderlo desde la partícula seleccionada hasta las siguientes, o en el centro de la vista
canvas-key-instrument-tab = Con la cinta o el transportador: elegir el extremo o el punto que mueven las flechas
canvas-key-instrument-move = Con la sonda, la cinta o el transportador: moverlo (su punto elegido) una décima de paso; Mayús una centésima

## Readouts and graphs
readout-heading = Energía y momento
readout-failed = La ejecución falló: los valores de su última muestra válida.
readout-potential = potencial (J)
readout-potential-field = potencial: campo (J)
readout-potential-springs = potencial: resortes (J)
readout-potential-gravitation = potencial: gravitación (J)
readout-potential-electrostatic = potencial: electrostática (J)
readout-press-play = Pulse Reproducir para ver las energías y el momento.
readout-kinetic = cinética (J)
readout-total = total (J)
readout-total-at-play = total al reproducir (J)
readout-damping = tomada por el amortiguamiento (J)
readout-friction = tomada por el rozamiento (J)
readout-impacts = tomada por los choques (J)
readout-ties = trabajo de varillas y cuerdas (J)
readout-error = error numérico
readout-momentum = momento (kg·m/s)
bar-kinetic = cinética
bar-damping = el amortiguamiento tomó
bar-friction = el rozamiento tomó
bar-impacts = los choques tomaron
bar-total-at-play = total al reproducir
bars-title = Barras de energía
bars-hint = Cada tipo de energía a la misma escala; los números están en la tabla de arriba
impacts-title = Choques ({ $count })
impacts-none = Todavía no hay choques.
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
graph-save-png-hint = Guardar una imagen de esta gráfica tal como se ve
graph-press-play = Pulse Reproducir: la gráfica se llena desde el inicio de la ejecución.

## Announcements for screen readers
announce-impact = A los { $time } s, { $particle } chocó con { $other }.{ $more ->
    [0] {""}
    [one] {" "}Y 1 choque más desde el último mensaje.
   *[other] {" "}Y { $more } choques más desde el último mensaje.
}
announce-wall = la pared
