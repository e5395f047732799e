<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>GraphQuantity</name>
    <message>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>angle (rad)</source>
        <translation>ángulo (rad)</translation>
    </message>
    <message>
        <source>vx (m/s)</source>
        <translation>vx (m/s)</translation>
    </message>
    <message>
        <source>vy (m/s)</source>
        <translation>vy (m/s)</translation>
    </message>
    <message>
        <source>speed (m/s)</source>
        <translation>rapidez (m/s)</translation>
    </message>
    <message>
        <source>ω (rad/s)</source>
        <translation>ω (rad/s)</translation>
    </message>
    <message>
        <source>px (kg·m/s)</source>
        <translation>px (kg·m/s)</translation>
    </message>
    <message>
        <source>py (kg·m/s)</source>
        <translation>py (kg·m/s)</translation>
    </message>
    <message>
        <source>kinetic energy (J)</source>
        <translation>energía cinética (J)</translation>
    </message>
    <message>
        <source>potential energy (J)</source>
        <translation>energía potencial (J)</translation>
    </message>
    <message>
        <source>kinetic + potential (J)</source>
        <translation>cinética + potencial (J)</translation>
    </message>
    <message>
        <source>collisions</source>
        <translation>colisiones</translation>
    </message>
    <message>
        <source>world kinetic energy (J)</source>
        <translation>energía cinética del mundo (J)</translation>
    </message>
    <message>
        <source>world potential energy (J)</source>
        <translation>energía potencial del mundo (J)</translation>
    </message>
    <message>
        <source>world elastic energy (J)</source>
        <translation>energía elástica del mundo (J)</translation>
    </message>
    <message>
        <source>world total energy (J)</source>
        <translation>energía total del mundo (J)</translation>
    </message>
    <message>
        <source>world px (kg·m/s)</source>
        <translation>px del mundo (kg·m/s)</translation>
    </message>
    <message>
        <source>world py (kg·m/s)</source>
        <translation>py del mundo (kg·m/s)</translation>
    </message>
    <message>
        <source>world angular momentum (kg·m²/s)</source>
        <translation>momento angular del mundo (kg·m²/s)</translation>
    </message>
    <message>
        <source>world collisions</source>
        <translation>colisiones del mundo</translation>
    </message>
</context>
<context>
    <name>RotationGesture</name>
    <message>
        <source>Rotate</source>
        <translation>Girar</translation>
    </message>
</context>
<context>
    <name>Tool</name>
    <message>
        <source>box</source>
        <translation>rectángulo</translation>
    </message>
    <message>
        <source>Draw box</source>
        <translation>Dibujar rectángulo</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>círculo</translation>
    </message>
    <message>
        <source>Draw circle</source>
        <translation>Dibujar círculo</translation>
    </message>
    <message>
        <source>ellipse</source>
        <translation>elipse</translation>
    </message>
    <message>
        <source>Draw ellipse</source>
        <translation>Dibujar elipse</translation>
    </message>
    <message>
        <source>Add pin</source>
        <translation>Añadir pasador</translation>
    </message>
    <message>
        <source>Add rod</source>
        <translation>Añadir varilla</translation>
    </message>
    <message>
        <source>Click on a body to pin it there: to the body under it, or to the world.</source>
        <translation>Haz clic en un cuerpo para sujetarlo ahí: al cuerpo de debajo o al mundo.</translation>
    </message>
    <message>
        <source>Drag from a body to another body, or to a point in space, to add a rod.</source>
        <translation>Arrastra desde un cuerpo hasta otro cuerpo, o hasta un punto del espacio, para añadir una varilla.</translation>
    </message>
    <message>
        <source>a polygon needs at least 3 different corners</source>
        <translation>un polígono necesita al menos 3 vértices distintos</translation>
    </message>
    <message>
        <source>a corner is not a finite point</source>
        <translation>un vértice no es un punto finito</translation>
    </message>
    <message>
        <source>two corners are at the same point</source>
        <translation>dos vértices están en el mismo punto</translation>
    </message>
    <message>
        <source>it is too small or flat to have an area</source>
        <translation>es demasiado pequeño o plano para tener área</translation>
    </message>
    <message>
        <source>its edges cross each other</source>
        <translation>sus lados se cruzan</translation>
    </message>
    <message>
        <source>Cannot close the polygon: %1. Move or remove a corner (Backspace), or press Escape to give up.</source>
        <translation>No se puede cerrar el polígono: %1. Mueve o quita un vértice (Retroceso), o pulsa Escape para desistir.</translation>
    </message>
    <message>
        <source>polygon</source>
        <translation>polígono</translation>
    </message>
    <message>
        <source>Draw polygon</source>
        <translation>Dibujar polígono</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Mover</translation>
    </message>
    <message>
        <source>Nudge</source>
        <translation>Desplazar poco a poco</translation>
    </message>
    <message>
        <source>Add spring</source>
        <translation>Añadir muelle</translation>
    </message>
    <message>
        <source>Drag from a body to another body, or to a point in space, to add a spring.</source>
        <translation>Arrastra desde un cuerpo hasta otro cuerpo, o hasta un punto del espacio, para añadir un muelle.</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Δx = %1 m, Δy = %2 m</source>
        <translation>Δx = %1 m, Δy = %2 m</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 (fixed)</source>
        <translation>%1 (fijo)</translation>
    </message>
    <message>
        <source>x = %1 m, y = %2 m</source>
        <translation>x = %1 m, y = %2 m</translation>
    </message>
    <message>
        <source>vx = %1 m/s, vy = %2 m/s</source>
        <translation>vx = %1 m/s, vy = %2 m/s</translation>
    </message>
    <message>
        <source>speed = %1 m/s</source>
        <translation>rapidez = %1 m/s</translation>
    </message>
    <message>
        <source>angle = %1 rad (%2°), ω = %3 rad/s</source>
        <translation>ángulo = %1 rad (%2°), ω = %3 rad/s</translation>
    </message>
    <message>
        <source>p = (%1, %2) kg·m/s</source>
        <translation>p = (%1; %2) kg·m/s</translation>
    </message>
    <message>
        <source>K = %1 J, U = %2 J, K + U = %3 J</source>
        <translation>K = %1 J, U = %2 J, K + U = %3 J</translation>
    </message>
    <message>
        <source>collisions: %1, touching now</source>
        <translation>colisiones: %1, en contacto ahora</translation>
    </message>
    <message>
        <source>collisions: %1</source>
        <translation>colisiones: %1</translation>
    </message>
</context>
<context>
    <name>impetus::app::App</name>
    <message>
        <source>--size must be WxH with both sides from 1 to %1 pixels, not “%2”</source>
        <translation>--size debe ser AnxAl con ambos lados de 1 a %1 píxeles, no «%2»</translation>
    </message>
    <message>
        <source>--run-for must be a number of seconds ≥ 0, not “%1”</source>
        <translation>--run-for debe ser un número de segundos ≥ 0, no «%1»</translation>
    </message>
    <message>
        <source>--run-for %1 s is %2 steps, more than the %3 allowed</source>
        <translation>--run-for %1 s son %2 pasos, más de los %3 permitidos</translation>
    </message>
    <message>
        <source>the simulation produced a non-finite number: body “%1”, by t = %2 s</source>
        <translation>la simulación produjo un número no finito: cuerpo «%1», hacia t = %2 s</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>Impetus, a 2D physics lab for the classroom.</source>
        <translation>Impetus, un laboratorio de física 2D para el aula.</translation>
    </message>
    <message>
        <source>Render the canvas to the PNG file FILE and exit.</source>
        <translation>Dibujar el lienzo en el archivo PNG ARCHIVO y salir.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>ARCHIVO</translation>
    </message>
    <message>
        <source>With --screenshot: simulate SECONDS first (default 0).</source>
        <translation>Con --screenshot: simular antes SEGUNDOS (por defecto 0).</translation>
    </message>
    <message>
        <source>SECONDS</source>
        <translation>SEGUNDOS</translation>
    </message>
    <message>
        <source>With --screenshot: the image size in pixels (default 1280x720).</source>
        <translation>Con --screenshot: el tamaño de la imagen en píxeles (por defecto 1280x720).</translation>
    </message>
    <message>
        <source>WxH</source>
        <translation>AnxAl</translation>
    </message>
    <message>
        <source>The scene file to open (default: the example scene).</source>
        <translation>El archivo de escena que abrir (por defecto, la escena de ejemplo).</translation>
    </message>
    <message>
        <source>expected at most one scene file, got %1</source>
        <translation>se esperaba como mucho un archivo de escena, se han dado %1</translation>
    </message>
    <message>
        <source>--run-for and --size need --screenshot</source>
        <translation>--run-for y --size necesitan --screenshot</translation>
    </message>
    <message>
        <source>Start the simulation as soon as the window opens.</source>
        <translation>Iniciar la simulación en cuanto se abra la ventana.</translation>
    </message>
    <message>
        <source>--run opens a window, --screenshot does not: give one of them</source>
        <translation>--run abre una ventana y --screenshot no: indique solo una de las dos</translation>
    </message>
</context>
<context>
    <name>impetus::view</name>
    <message>
        <source>cannot read %1: %2</source>
        <translation>no se puede leer %1: %2</translation>
    </message>
</context>
<context>
    <name>impetus::view::Autosave</name>
    <message>
        <source>cannot write the autosave &apos;%1&apos;: %2</source>
        <translation>no se puede escribir la copia automática «%1»: %2</translation>
    </message>
    <message>
        <source>%1: not a description of an autosave: %2</source>
        <translation>%1: no es la descripción de una copia automática: %2</translation>
    </message>
    <message>
        <source>%1: cannot read it: %2</source>
        <translation>%1: no se puede leer: %2</translation>
    </message>
    <message>
        <source>Restore Unsaved Work</source>
        <translation>Recuperar el trabajo sin guardar</translation>
    </message>
    <message>
        <source>An autosave from %1 cannot be read and was not restored. It was kept in “%2”.</source>
        <translation>Una copia automática del %1 no se puede leer y no se ha recuperado. Se ha guardado en «%2».</translation>
    </message>
    <message>
        <source>Impetus was not closed properly. Your work on “%1” was saved automatically at %2.</source>
        <translation>Impetus no se cerró correctamente. Su trabajo en «%1» se guardó automáticamente el %2.</translation>
    </message>
    <message>
        <source>Restore it? Discarding deletes the autosave.</source>
        <translation>¿Recuperarlo? Descartar borra la copia automática.</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Recuperar</translation>
    </message>
</context>
<context>
    <name>impetus::view::CanvasInstruments</name>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>kg·m/s</source>
        <translation>kg·m/s</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>gravedad</translation>
    </message>
    <message>
        <source>springs</source>
        <translation>muelles</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>rozamiento del aire</translation>
    </message>
    <message>
        <source>contact normal</source>
        <translation>fuerza normal</translation>
    </message>
    <message>
        <source>friction</source>
        <translation>rozamiento</translation>
    </message>
    <message>
        <source>joints</source>
        <translation>uniones</translation>
    </message>
    <message>
        <source>1 %1 = %2 m</source>
        <translation>1 %1 = %2 m</translation>
    </message>
    <message>
        <source>velocity: %1</source>
        <translation>velocidad: %1</translation>
    </message>
    <message>
        <source>acceleration: %1</source>
        <translation>aceleración: %1</translation>
    </message>
    <message>
        <source>net force: %1</source>
        <translation>fuerza neta: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>momentum: %1</source>
        <translation>momento lineal: %1</translation>
    </message>
</context>
<context>
    <name>impetus::view::CanvasView</name>
    <message>
        <source>Simulation canvas</source>
        <translation>Lienzo de la simulación</translation>
    </message>
    <message>
        <source>The bodies, springs and joints of the scene, in metres, y up</source>
        <translation>Los cuerpos, muelles y uniones de la escena, en metros, con y hacia arriba</translation>
    </message>
    <message>
        <source>%L1 m</source>
        <translation>%L1 m</translation>
    </message>
</context>
<context>
    <name>impetus::view::CollisionInspector</name>
    <message>
        <source>Pause the run to bring the log up to date.</source>
        <translation>Pausa la simulación para actualizar el registro.</translation>
    </message>
    <message>
        <source>No collisions yet. Run or step the scene, then pause.</source>
        <translation>Aún no hay colisiones. Ejecuta la escena o avánzala paso a paso, y luego pausa.</translation>
    </message>
    <message numerus="yes">
        <source>%n collision(s). Click one to see its impulse.</source>
        <translation>
            <numerusform>%n colisión. Haz clic en ella para ver su impulso.</numerusform>
            <numerusform>%n colisiones. Haz clic en una para ver su impulso.</numerusform>
        </translation>
    </message>
    <message>
        <source>t = %1 s: %2 and %3, impulse %4 N·s</source>
        <translation>t = %1 s: %2 y %3, impulso %4 N·s</translation>
    </message>
    <message>
        <source>&lt;h3&gt;%1 and %2 at t = %3 s&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;%1 y %2 en t = %3 s&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Normal n = %1 (from %2 to %3). Total normal impulse this step, as logged: &lt;b&gt;%4 N·s&lt;/b&gt;; relative normal speed %5 m/s before, %6 m/s after the step.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal n = %1 (de %2 a %3). Impulso normal total en este paso, según el registro: &lt;b&gt;%4 N·s&lt;/b&gt;; velocidad normal relativa %5 m/s antes y %6 m/s después del paso.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;No impact: the bodies met slower than the restitution threshold (%1 m/s), or were already touching, so the contact forces alone stopped the approach. No bounce, e plays no part.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Sin choque: los cuerpos se encontraron más despacio que el umbral de restitución (%1 m/s), o ya estaban en contacto, así que solo las fuerzas de contacto detuvieron el acercamiento. No hay rebote; e no interviene.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h4&gt;Impact %1 of %2&lt;/h4&gt;</source>
        <translation>&lt;h4&gt;Choque %1 de %2&lt;/h4&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;m&lt;sub&gt;A&lt;/sub&gt; = %1 kg, 1/I&lt;sub&gt;A&lt;/sub&gt; = %2 1/(kg·m²); m&lt;sub&gt;B&lt;/sub&gt; = %3 kg, 1/I&lt;sub&gt;B&lt;/sub&gt; = %4 1/(kg·m²); e = %5, μ = %6&lt;/p&gt;</source>
        <translation>&lt;p&gt;m&lt;sub&gt;A&lt;/sub&gt; = %1 kg, 1/I&lt;sub&gt;A&lt;/sub&gt; = %2 1/(kg·m²); m&lt;sub&gt;B&lt;/sub&gt; = %3 kg, 1/I&lt;sub&gt;B&lt;/sub&gt; = %4 1/(kg·m²); e = %5; μ = %6&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Point %1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Punto %1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;r&lt;sub&gt;A&lt;/sub&gt; = %1 m, r&lt;sub&gt;B&lt;/sub&gt; = %2 m; r&lt;sub&gt;A&lt;/sub&gt;×n = %3 m, r&lt;sub&gt;B&lt;/sub&gt;×n = %4 m&lt;br&gt;relative normal speed before v&lt;sub&gt;n&lt;/sub&gt; = %5 m/s&lt;/p&gt;</source>
        <translation>&lt;p&gt;r&lt;sub&gt;A&lt;/sub&gt; = %1 m, r&lt;sub&gt;B&lt;/sub&gt; = %2 m; r&lt;sub&gt;A&lt;/sub&gt;×n = %3 m, r&lt;sub&gt;B&lt;/sub&gt;×n = %4 m&lt;br&gt;velocidad normal relativa antes v&lt;sub&gt;n&lt;/sub&gt; = %5 m/s&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; / (1/m&lt;sub&gt;A&lt;/sub&gt; + 1/m&lt;sub&gt;B&lt;/sub&gt; + (r&lt;sub&gt;A&lt;/sub&gt;×n)²/I&lt;sub&gt;A&lt;/sub&gt; + (r&lt;sub&gt;B&lt;/sub&gt;×n)²/I&lt;sub&gt;B&lt;/sub&gt;)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / (%3 + %4 + (%5)²·%6 + (%7)²·%8)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / %9 = &lt;b&gt;%10 N·s&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; / (1/m&lt;sub&gt;A&lt;/sub&gt; + 1/m&lt;sub&gt;B&lt;/sub&gt; + (r&lt;sub&gt;A&lt;/sub&gt;×n)²/I&lt;sub&gt;A&lt;/sub&gt; + (r&lt;sub&gt;B&lt;/sub&gt;×n)²/I&lt;sub&gt;B&lt;/sub&gt;)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / (%3 + %4 + (%5)²·%6 + (%7)²·%8)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / %9 = &lt;b&gt;%10 N·s&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;|v&lt;sub&gt;n&lt;/sub&gt;| is below the restitution threshold (%1 m/s): the impulse only stops the approach, e counts as 0.&lt;/p&gt;</source>
        <translation>&lt;p&gt;|v&lt;sub&gt;n&lt;/sub&gt;| está por debajo del umbral de restitución (%1 m/s): el impulso solo detiene el acercamiento; e cuenta como 0.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Two points struck at once: the engine solves K·j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; for both together, K = [[%1, %2], [%3, %4]] 1/kg, and applied &lt;b&gt;%5 N·s&lt;/b&gt; here (the formula above is this point alone).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Dos puntos golpeados a la vez: la simulación resuelve K·j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; para ambos juntos, K = [[%1; %2]; [%3; %4]] 1/kg, y aplicó aquí &lt;b&gt;%5 N·s&lt;/b&gt; (la fórmula de arriba es solo para este punto).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;The engine applied %1 N·s.&lt;/p&gt;</source>
        <translation>&lt;p&gt;La simulación aplicó %1 N·s.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Normal speed after: v&lt;sub&gt;n&lt;/sub&gt;′ = %1 m/s (−e·v&lt;sub&gt;n&lt;/sub&gt; = %2 m/s)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Velocidad normal después: v&lt;sub&gt;n&lt;/sub&gt;′ = %1 m/s (−e·v&lt;sub&gt;n&lt;/sub&gt; = %2 m/s)&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Friction: tangential speed v&lt;sub&gt;t&lt;/sub&gt; = %1 m/s; stopping it needs −v&lt;sub&gt;t&lt;/sub&gt;/K&lt;sub&gt;t&lt;/sub&gt; = %2 N·s with K&lt;sub&gt;t&lt;/sub&gt; = %3 1/kg; the limit μ·j = %4 N·s; applied %5 N·s: &lt;b&gt;%6&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Rozamiento: velocidad tangencial v&lt;sub&gt;t&lt;/sub&gt; = %1 m/s; detenerla requiere −v&lt;sub&gt;t&lt;/sub&gt;/K&lt;sub&gt;t&lt;/sub&gt; = %2 N·s con K&lt;sub&gt;t&lt;/sub&gt; = %3 1/kg; el límite es μ·j = %4 N·s; aplicado %5 N·s: &lt;b&gt;%6&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>it slid (friction at its limit)</source>
        <translation>se deslizó (rozamiento en su límite)</translation>
    </message>
    <message>
        <source>it stuck (sliding stopped)</source>
        <translation>se adhirió (el deslizamiento se detuvo)</translation>
    </message>
    <message>
        <source>&lt;p&gt;Momentum of the pair: %1 → %2 kg·m/s&lt;br&gt;Kinetic energy of the pair: %3 → %4 J (%5 J)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Momento lineal del par: %1 → %2 kg·m/s&lt;br&gt;Energía cinética del par: %3 → %4 J (%5 J)&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;A fixed body takes any momentum: the pair&apos;s momentum changes by the impulse.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Un cuerpo fijo absorbe cualquier momento lineal: el momento lineal del par cambia en lo que vale el impulso.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <extracomment>A vector: its x and y. Where the decimal separator is a comma, separate them with a semicolon: (0,6; -0,8).</extracomment>
        <translation>(%1; %2)</translation>
    </message>
</context>
<context>
    <name>impetus::view::EnergyLedgerChart</name>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>energy (J)</source>
        <translation>energía (J)</translation>
    </message>
    <message>
        <source>Kinetic</source>
        <translation>Cinética</translation>
    </message>
    <message>
        <source>Potential</source>
        <translation>Potencial</translation>
    </message>
    <message>
        <source>Elastic</source>
        <translation>Elástica</translation>
    </message>
    <message>
        <source>Impacts</source>
        <translation>Choques</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Rozamiento</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Rozamiento del aire</translation>
    </message>
    <message>
        <source>Spring damping</source>
        <translation>Amortiguación de los muelles</translation>
    </message>
    <message>
        <source>Soft damping</source>
        <translation>Amortiguación (blando)</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>Uniones</translation>
    </message>
    <message>
        <source>Position correction</source>
        <translation>Corrección de posición</translation>
    </message>
    <message>
        <source>Drift</source>
        <translation>Deriva</translation>
    </message>
    <message>
        <source>Run the simulation to fill the energy ledger.</source>
        <translation>Ejecuta la simulación para llenar el balance de energía.</translation>
    </message>
    <message>
        <source>Start %1 J = now %2 J + losses %3 J (off by %4 J); drift %5 J</source>
        <translation>Inicio %1 J = ahora %2 J + pérdidas %3 J (desviación %4 J); deriva %5 J</translation>
    </message>
</context>
<context>
    <name>impetus::view::Examples</name>
    <message>
        <source>Billiards break</source>
        <translation>Saque de billar</translation>
    </message>
    <message>
        <source>Box stack and overhang</source>
        <translation>Pila de cajas en voladizo</translation>
    </message>
    <message>
        <source>Default scene</source>
        <translation>Escena predeterminada</translation>
    </message>
    <message>
        <source>Block on an incline</source>
        <translation>Bloque en un plano inclinado</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle</source>
        <translation>Péndulo de Newton</translation>
    </message>
    <message>
        <source>Pendulum</source>
        <translation>Péndulo</translation>
    </message>
    <message>
        <source>Projectile over the ground</source>
        <translation>Proyectil sobre el suelo</translation>
    </message>
    <message>
        <source>Pyramid</source>
        <translation>Pirámide</translation>
    </message>
    <message>
        <source>Soft bodies: rigid and soft side by side</source>
        <translation>Cuerpos blandos: rígido y blando lado a lado</translation>
    </message>
    <message>
        <source>Spaceship and asteroids</source>
        <translation>Nave espacial y asteroides</translation>
    </message>
    <message>
        <source>Chain of springs</source>
        <translation>Cadena de muelles</translation>
    </message>
    <message>
        <source>Lesson: momentum in a cart crash</source>
        <translation>Lección: momento lineal en un choque de carritos</translation>
    </message>
    <message>
        <source>Lesson: friction on an incline</source>
        <translation>Lección: rozamiento en un plano inclinado</translation>
    </message>
    <message>
        <source>Lesson: pendulum period and length</source>
        <translation>Lección: periodo y longitud del péndulo</translation>
    </message>
    <message>
        <source>Mass on a spring</source>
        <translation>Masa en un muelle</translation>
    </message>
    <message>
        <source>Lesson: spring period and stiffness</source>
        <translation>Lección: periodo y constante de un muelle</translation>
    </message>
    <message>
        <source>Lesson: tuning a pendulum</source>
        <translation>Lección: afinar un péndulo</translation>
    </message>
</context>
<context>
    <name>impetus::view::GraphPanel</name>
    <message>
        <source>Graph</source>
        <translation>Gráfico</translation>
    </message>
    <message>
        <source>Body plotted</source>
        <translation>Cuerpo representado</translation>
    </message>
    <message>
        <source>Quantity on the vertical axis</source>
        <translation>Magnitud en el eje vertical</translation>
    </message>
    <message>
        <source>Quantity on the horizontal axis</source>
        <translation>Magnitud en el eje horizontal</translation>
    </message>
    <message>
        <source>Value under the cursor</source>
        <translation>Valor bajo el cursor</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Exportar CSV…</translation>
    </message>
    <message>
        <source>Save every recorded step as a table (time, body and the plotted quantities)</source>
        <translation>Guardar cada paso registrado como tabla (tiempo, cuerpo y las magnitudes representadas)</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>Exportar PNG…</translation>
    </message>
    <message>
        <source>Save the graph as a picture</source>
        <translation>Guardar el gráfico como imagen</translation>
    </message>
    <message>
        <source>against</source>
        <translation>frente a</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 de %2</translation>
    </message>
    <message>
        <source>%1 against %2 of %3</source>
        <translation>%1 frente a %2 de %3</translation>
    </message>
    <message>
        <source>%1 = %2, %3 = %4</source>
        <translation>%1 = %2; %3 = %4</translation>
    </message>
    <message>
        <source>Cannot write “%1”: %2</source>
        <translation>No se puede escribir «%1»: %2</translation>
    </message>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>No se puede escribir la imagen «%1».</translation>
    </message>
    <message>
        <source>Export Graph Data</source>
        <translation>Exportar los datos del gráfico</translation>
    </message>
    <message>
        <source>CSV tables (*.csv);;All files (*)</source>
        <translation>Tablas CSV (*.csv);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>No se puede exportar</translation>
    </message>
    <message>
        <source>Export Graph Picture</source>
        <translation>Exportar la imagen del gráfico</translation>
    </message>
    <message>
        <source>PNG pictures (*.png);;All files (*)</source>
        <translation>Imágenes PNG (*.png);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Drag a box over the plot to zoom in on it; right-click to see everything again</source>
        <translation>Arrastre un rectángulo sobre el gráfico para ampliarlo; clic derecho para volver a verlo todo</translation>
    </message>
</context>
<context>
    <name>impetus::view::IntegratorGhosts</name>
    <message>
        <source>Explicit Euler</source>
        <translation>Euler explícito</translation>
    </message>
    <message>
        <source>Semi-implicit Euler</source>
        <translation>Euler semiimplícito</translation>
    </message>
    <message>
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <source>1/%1 s</source>
        <translation>1/%1 s</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Ghosts, h = %1</source>
        <translation>Fantasmas, h = %1</translation>
    </message>
</context>
<context>
    <name>impetus::view::IntegratorGhostsPanel</name>
    <message>
        <source>Energy error</source>
        <translation>Error de energía</translation>
    </message>
    <message>
        <source>Position error</source>
        <translation>Error de posición</translation>
    </message>
    <message>
        <source>Energy error: (E − E₀)/|E₀|. Position error: the largest distance of a body from the textbook solution.</source>
        <translation>Error de energía: (E − E₀)/|E₀|. Error de posición: la mayor distancia de un cuerpo a la solución del libro de texto.</translation>
    </message>
    <message>
        <source>Ghosts&apos; time step h:</source>
        <translation>Paso de tiempo h de los fantasmas:</translation>
    </message>
    <message>
        <source>Ghosts&apos; time step</source>
        <translation>Paso de tiempo de los fantasmas</translation>
    </message>
    <message>
        <source>The ghosts&apos; fixed time step, from 1/1000 s (left) to 1/30 s (right)</source>
        <translation>El paso de tiempo fijo de los fantasmas, de 1/1000 s (izquierda) a 1/30 s (derecha)</translation>
    </message>
    <message>
        <source>Largest position error in %1 s against the time step</source>
        <translation>Mayor error de posición en %1 s frente al paso de tiempo</translation>
    </message>
    <message>
        <source>time step h (s)</source>
        <translation>paso de tiempo h (s)</translation>
    </message>
    <message>
        <source>position error (m)</source>
        <translation>error de posición (m)</translation>
    </message>
    <message>
        <source>ghosts&apos; h</source>
        <translation>h de los fantasmas</translation>
    </message>
    <message>
        <source>Analytic solution: free flight, x = x₀ + v₀t + ½gt², until the first contact.</source>
        <translation>Solución analítica: vuelo libre, x = x₀ + v₀t + ½gt², hasta el primer contacto.</translation>
    </message>
    <message>
        <source>Analytic solution: a mass on a spring, x = x_eq + (x₀ − x_eq)·cos ωt + (v₀/ω)·sin ωt, ω = √(k/m).</source>
        <translation>Solución analítica: una masa en un muelle, x = x_eq + (x₀ − x_eq)·cos ωt + (v₀/ω)·sin ωt, ω = √(k/m).</translation>
    </message>
    <message>
        <source>Analytic solution: a pendulum at any amplitude, sin(θ/2) = k·sn(ω₀t + u₀, k), ω₀ = √(g/L), until the first contact.</source>
        <translation>Solución analítica: un péndulo con cualquier amplitud, sin(θ/2) = k·sn(ω₀t + u₀, k), ω₀ = √(g/L), hasta el primer contacto.</translation>
    </message>
    <message>
        <source>No analytic solution for this scene: only the energy errors can be compared.</source>
        <translation>No hay solución analítica para esta escena: solo se pueden comparar los errores de energía.</translation>
    </message>
    <message>
        <source>Bodies held by joints move by semi-implicit Euler whichever integrator is chosen, so their ghosts lie on one another.</source>
        <translation>Los cuerpos sujetos por uniones se mueven con Euler semiimplícito sea cual sea el integrador elegido, así que sus fantasmas quedan superpuestos.</translation>
    </message>
    <message>
        <source>diverged at t = %1 s</source>
        <translation>divergió en t = %1 s</translation>
    </message>
    <message>
        <source>diverged</source>
        <translation>divergió</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>no analytic solution after a contact</source>
        <translation>sin solución analítica tras un contacto</translation>
    </message>
    <message>
        <source>no analytic solution</source>
        <translation>sin solución analítica</translation>
    </message>
    <message>
        <source>Ghosts at t = %1 s after their start: n = %2 steps of h = %3%4</source>
        <translation>Fantasmas en t = %1 s desde su inicio: n = %2 pasos de h = %3%4</translation>
    </message>
    <message>
        <source> (catching up)</source>
        <translation> (recuperando el retraso)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 exact to rounding</source>
        <translation>%1 exacto salvo redondeo</translation>
    </message>
    <message>
        <source>No analytic solution for this scene: no error to plot.</source>
        <translation>No hay solución analítica para esta escena: no hay error que representar.</translation>
    </message>
    <message>
        <source>Fitted slopes (the method&apos;s order): %1</source>
        <translation>Pendientes ajustadas (el orden del método): %1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>; </translation>
    </message>
    <message>
        <source>Integrator Ghosts</source>
        <translation>Fantasmas de los integradores</translation>
    </message>
    <message>
        <source>Compare &amp;Integrators</source>
        <translation>&amp;Comparar integradores</translation>
    </message>
    <message>
        <source>Run the scene under explicit Euler, semi-implicit Euler and RK4 beside the real run, drawn as ghosts, with their errors</source>
        <translation>Simular la escena con Euler explícito, Euler semiimplícito y RK4 junto a la simulación real, dibujadas como fantasmas, con sus errores</translation>
    </message>
</context>
<context>
    <name>impetus::view::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>The language changes the next time Impetus starts.</source>
        <translation>El idioma cambiará la próxima vez que se inicie Impetus.</translation>
    </message>
    <message>
        <source>System Language</source>
        <translation>Idioma del sistema</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonDock</name>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>Lesson (editing)</source>
        <translation>Lección (en edición)</translation>
    </message>
    <message>
        <source>&amp;Lesson</source>
        <translation>&amp;Lección</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>Lift the lesson&apos;s locks and write its title, instructions, locks and questions</source>
        <translation>Levantar los bloqueos de la lección y escribir su título, instrucciones, bloqueos y preguntas</translation>
    </message>
    <message>
        <source>Create lesson</source>
        <translation>Crear lección</translation>
    </message>
    <message>
        <source>&amp;Remove Lesson</source>
        <translation>&amp;Quitar la lección</translation>
    </message>
    <message>
        <source>Take the lesson out of the scene: no locks, no questions</source>
        <translation>Quitar la lección de la escena: sin bloqueos ni preguntas</translation>
    </message>
    <message>
        <source>Remove lesson</source>
        <translation>Quitar la lección</translation>
    </message>
    <message>
        <source>Lesson &amp;Panel</source>
        <translation>&amp;Panel de la lección</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonEditor</name>
    <message>
        <source>Lesson editor</source>
        <translation>Editor de la lección</translation>
    </message>
    <message>
        <source>Lesson title</source>
        <translation>Título de la lección</translation>
    </message>
    <message>
        <source>&amp;Title</source>
        <translation>&amp;Título</translation>
    </message>
    <message>
        <source>Instructions</source>
        <translation>Instrucciones</translation>
    </message>
    <message>
        <source>Plain text or simple Markdown: **bold**, *italic*, lists</source>
        <translation>Texto simple o Markdown sencillo: **negrita**, *cursiva*, listas</translation>
    </message>
    <message>
        <source>What students should do; **bold**, *italic* and lists work</source>
        <translation>Qué deben hacer los alumnos; funcionan **negrita**, *cursiva* y listas</translation>
    </message>
    <message>
        <source>&amp;Instructions</source>
        <translation>&amp;Instrucciones</translation>
    </message>
    <message>
        <source>Students may change (ticked; everything else is locked):</source>
        <translation>Los alumnos pueden cambiar (lo marcado; todo lo demás queda bloqueado):</translation>
    </message>
    <message>
        <source>What students may change</source>
        <translation>Qué pueden cambiar los alumnos</translation>
    </message>
    <message>
        <source>&amp;Questions</source>
        <translation>&amp;Preguntas</translation>
    </message>
    <message>
        <source>Questions</source>
        <translation>Preguntas</translation>
    </message>
    <message>
        <source>Question</source>
        <translation>Pregunta</translation>
    </message>
    <message>
        <source>Answer</source>
        <translation>Respuesta</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <source>Tolerance (±)</source>
        <translation>Tolerancia (±)</translation>
    </message>
    <message>
        <source>Add Question</source>
        <translation>Añadir pregunta</translation>
    </message>
    <message>
        <source>Remove Question</source>
        <translation>Quitar pregunta</translation>
    </message>
    <message>
        <source>Remove the current question</source>
        <translation>Quitar la pregunta actual</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>World settings</source>
        <translation>Ajustes del mundo</translation>
    </message>
    <message>
        <source>A lesson needs a title.</source>
        <translation>Una lección necesita un título.</translation>
    </message>
    <message>
        <source>Change lesson title</source>
        <translation>Cambiar el título de la lección</translation>
    </message>
    <message>
        <source>Change lesson instructions</source>
        <translation>Cambiar las instrucciones de la lección</translation>
    </message>
    <message>
        <source>Change which world settings students may change</source>
        <translation>Cambiar qué ajustes del mundo pueden cambiar los alumnos</translation>
    </message>
    <message>
        <source>Change what students may change of “%1”</source>
        <translation>Cambiar qué pueden cambiar los alumnos de «%1»</translation>
    </message>
    <message>
        <source>A question needs a prompt.</source>
        <translation>Una pregunta necesita un enunciado.</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number.</source>
        <translation>%1: «%2» no es un número.</translation>
    </message>
    <message>
        <source>Tolerance must be greater than 0 (got %1).</source>
        <translation>La tolerancia debe ser mayor que 0 (se indicó %1).</translation>
    </message>
    <message>
        <source>Edit question %1</source>
        <translation>Editar la pregunta %1</translation>
    </message>
    <message>
        <source>New question</source>
        <translation>Nueva pregunta</translation>
    </message>
    <message>
        <source>Add question</source>
        <translation>Añadir pregunta</translation>
    </message>
    <message>
        <source>Remove question %1</source>
        <translation>Quitar la pregunta %1</translation>
    </message>
    <message>
        <source>the world</source>
        <translation>el mundo</translation>
    </message>
    <message>
        <source>Spring %1 (%2 to %3)</source>
        <translation>Muelle %1 (entre %2 y %3)</translation>
    </message>
    <message>
        <source>Change what students may change of spring %1</source>
        <translation>Cambiar qué pueden cambiar los alumnos del muelle %1</translation>
    </message>
    <message>
        <source>Pin %1 (%2 to %3)</source>
        <translation>Pasador %1 (entre %2 y %3)</translation>
    </message>
    <message>
        <source>Rod %1 (%2 to %3)</source>
        <translation>Varilla %1 (entre %2 y %3)</translation>
    </message>
    <message>
        <source>Change what students may change of joint %1</source>
        <translation>Cambiar qué pueden cambiar los alumnos de la unión %1</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonPanel</name>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>Lesson title</source>
        <translation>Título de la lección</translation>
    </message>
    <message>
        <source>Instructions</source>
        <translation>Instrucciones</translation>
    </message>
    <message>
        <source>What you may change</source>
        <translation>Qué puedes cambiar</translation>
    </message>
    <message>
        <source>No lesson</source>
        <translation>Sin lección</translation>
    </message>
    <message>
        <source>This scene has no lesson. A teacher can write one with Lesson › Edit.</source>
        <translation>Esta escena no tiene lección. Un profesor puede escribir una con Lección › Editar.</translation>
    </message>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source>Answer to question %1</source>
        <translation>Respuesta a la pregunta %1</translation>
    </message>
    <message>
        <source>your answer</source>
        <translation>tu respuesta</translation>
    </message>
    <message>
        <source>Unit: %1</source>
        <translation>Unidad: %1</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Comprobar</translation>
    </message>
    <message>
        <source>Check answer %1</source>
        <translation>Comprobar la respuesta %1</translation>
    </message>
    <message>
        <source>Verdict on answer %1</source>
        <translation>Resultado de la respuesta %1</translation>
    </message>
    <message>
        <source>Type your answer first.</source>
        <translation>Escribe primero tu respuesta.</translation>
    </message>
    <message>
        <source>“%1” is not a number.</source>
        <translation>«%1» no es un número.</translation>
    </message>
    <message>
        <source>Right! You are %1 off; up to %2 counts as right.</source>
        <translation>¡Correcto! Te desvías %1; hasta %2 cuenta como correcto.</translation>
    </message>
    <message>
        <source>Wrong: %1 too high (up to %2 off counts as right).</source>
        <translation>Incorrecto: %1 demasiado alto (una desviación de hasta %2 cuenta como correcta).</translation>
    </message>
    <message>
        <source>Wrong: %1 too low (up to %2 off counts as right).</source>
        <translation>Incorrecto: %1 demasiado bajo (una desviación de hasta %2 cuenta como correcta).</translation>
    </message>
    <message>
        <source>Lesson › Edit is on: nothing is locked.</source>
        <translation>Lección › Editar está activo: nada está bloqueado.</translation>
    </message>
    <message>
        <source>“%1”: %2</source>
        <translation>«%1»: %2</translation>
    </message>
    <message>
        <source>world: %1</source>
        <translation>mundo: %1</translation>
    </message>
    <message>
        <source>Everything in this scene is locked by the lesson.</source>
        <translation>Todo en esta escena está bloqueado por la lección.</translation>
    </message>
    <message>
        <source>You may change %1. Everything else is locked by the lesson.</source>
        <translation>Puedes cambiar %1. Todo lo demás está bloqueado por la lección.</translation>
    </message>
    <message>
        <source>spring %1: %2</source>
        <translation>muelle %1: %2</translation>
    </message>
    <message>
        <source>joint %1: %2</source>
        <translation>unión %1: %2</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonSession</name>
    <message>
        <source>Locked by the lesson: the %1 of “%2” can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: no se puede cambiar «%2» (%1).</translation>
    </message>
    <message>
        <source>Locked by the lesson: the %1 can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: este ajuste (%1) no se puede cambiar.</translation>
    </message>
    <message>
        <source>Locked by the lesson: “%1” can&apos;t be turned.</source>
        <translation>Bloqueado por la lección: «%1» no se puede girar.</translation>
    </message>
    <message>
        <source>Locked by the lesson: “%1” can&apos;t be moved.</source>
        <translation>Bloqueado por la lección: «%1» no se puede mover.</translation>
    </message>
    <message>
        <source>Locked by the lesson: nothing can be deleted.</source>
        <translation>Bloqueado por la lección: no se puede eliminar nada.</translation>
    </message>
    <message>
        <source>Locked by the lesson: new bodies, springs and joints can&apos;t be added.</source>
        <translation>Bloqueado por la lección: no se pueden añadir cuerpos, muelles ni uniones.</translation>
    </message>
    <message>
        <source>Locked by the lesson: this body can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: este cuerpo no se puede cambiar.</translation>
    </message>
    <message>
        <source>Locked by the lesson. You may change its %1.</source>
        <translation>Bloqueado por la lección. Puedes cambiar: %1.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the world settings can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: los ajustes del mundo no se pueden cambiar.</translation>
    </message>
    <message>
        <source>Locked by the lesson. You may change the %1.</source>
        <translation>Bloqueado por la lección. Puedes cambiar: %1.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the %1 of spring %2 can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: no se puede cambiar el muelle %2 (%1).</translation>
    </message>
    <message>
        <source>Locked by the lesson: spring %1 can&apos;t be joined to other bodies.</source>
        <translation>Bloqueado por la lección: el muelle %1 no se puede unir a otros cuerpos.</translation>
    </message>
    <message>
        <source>Locked by the lesson: this spring can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: este muelle no se puede cambiar.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the %1 of joint %2 can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: no se puede cambiar la unión %2 (%1).</translation>
    </message>
    <message>
        <source>Locked by the lesson: joint %1 can&apos;t be changed to another type or to other bodies.</source>
        <translation>Bloqueado por la lección: la unión %1 no se puede cambiar a otro tipo ni unir a otros cuerpos.</translation>
    </message>
    <message>
        <source>Locked by the lesson: this joint can&apos;t be changed.</source>
        <translation>Bloqueado por la lección: esta unión no se puede cambiar.</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>bisagra</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonText</name>
    <message>
        <source>name</source>
        <translation>nombre</translation>
    </message>
    <message>
        <source>size</source>
        <translation>tamaño</translation>
    </message>
    <message>
        <source>position</source>
        <translation>posición</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>ángulo</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <source>angular velocity</source>
        <translation>velocidad angular</translation>
    </message>
    <message>
        <source>mass</source>
        <translation>masa</translation>
    </message>
    <message>
        <source>restitution</source>
        <translation>restitución</translation>
    </message>
    <message>
        <source>friction</source>
        <translation>rozamiento</translation>
    </message>
    <message>
        <source>fixed</source>
        <translation>fijo</translation>
    </message>
    <message>
        <source>colour</source>
        <translation>color</translation>
    </message>
    <message>
        <source>soft mode</source>
        <translation>modo blando</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>gravedad</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrador</translation>
    </message>
    <message>
        <source>time step</source>
        <translation>paso de tiempo</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>rozamiento del aire</translation>
    </message>
    <message>
        <source>stiffness</source>
        <translation>constante elástica</translation>
    </message>
    <message>
        <source>damping</source>
        <translation>amortiguación</translation>
    </message>
    <message>
        <source>rest length</source>
        <translation>longitud en reposo</translation>
    </message>
    <message>
        <source>anchors</source>
        <translation>puntos de anclaje</translation>
    </message>
</context>
<context>
    <name>impetus::view::MainWindow</name>
    <message>
        <source>Impetus main window</source>
        <translation>Ventana principal de Impetus</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <source>Start an empty scene</source>
        <translation>Empezar una escena vacía</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Abrir…</translation>
    </message>
    <message>
        <source>Open a scene file</source>
        <translation>Abrir un archivo de escena</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Save the scene to its file</source>
        <translation>Guardar la escena en su archivo</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Guardar &amp;como…</translation>
    </message>
    <message>
        <source>Save the scene to a new file</source>
        <translation>Guardar la escena en un archivo nuevo</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Eliminar</translation>
    </message>
    <message>
        <source>Delete the selection, and the springs and joints on deleted bodies</source>
        <translation>Eliminar la selección y los muelles y uniones de los cuerpos eliminados</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Seleccionar &amp;todo</translation>
    </message>
    <message>
        <source>&amp;Snap to Grid</source>
        <translation>&amp;Ajustar a la cuadrícula</translation>
    </message>
    <message>
        <source>Place and move points on the grid lines&apos; crossings</source>
        <translation>Colocar y mover puntos en los cruces de la cuadrícula</translation>
    </message>
    <message>
        <source>Show Soft-Body &amp;Ellipses</source>
        <translation>Mostrar e&amp;lipses de los cuerpos blandos</translation>
    </message>
    <message>
        <source>Draw the small ellipses a soft body is made of</source>
        <translation>Dibujar las pequeñas elipses de las que está hecho un cuerpo blando</translation>
    </message>
    <message>
        <source>Show Soft-Body S&amp;train</source>
        <translation>Mostrar &amp;deformación de los cuerpos blandos</translation>
    </message>
    <message>
        <source>Draw a soft body&apos;s springs coloured by strain: blue compressed, grey at rest, red stretched</source>
        <translation>Dibujar los muelles de un cuerpo blando coloreados según su deformación: azul comprimido, gris en reposo, rojo estirado</translation>
    </message>
    <message>
        <source>&amp;Frame Scene</source>
        <translation>&amp;Encuadrar la escena</translation>
    </message>
    <message>
        <source>Zoom to show every body</source>
        <translation>Ajustar el zoom para ver todos los cuerpos</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>Run the simulation (Space)</source>
        <translation>Ejecutar la simulación (Espacio)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Advance one time step (→)</source>
        <translation>Avanzar un paso de tiempo (→)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Go back to the state at the last Play (R)</source>
        <translation>Volver al estado del último inicio (R)</translation>
    </message>
    <message>
        <source>Select</source>
        <translation>Seleccionar</translation>
    </message>
    <message>
        <source>Select, move (drag) and nudge (arrow keys); Ctrl+drag turns</source>
        <translation>Seleccionar, mover (arrastrar) y desplazar poco a poco (flechas); Ctrl+arrastrar gira</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Girar</translation>
    </message>
    <message>
        <source>Drag to turn a body or the selection about its centre</source>
        <translation>Arrastra para girar un cuerpo o la selección alrededor de su centro</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polígono</translation>
    </message>
    <message>
        <source>Click the corners; click the first one, press Enter or double-click to close</source>
        <translation>Haz clic en los vértices; para cerrar, haz clic en el primero, pulsa Intro o haz doble clic</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Rectángulo</translation>
    </message>
    <message>
        <source>Drag from corner to corner</source>
        <translation>Arrastra de esquina a esquina</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Círculo</translation>
    </message>
    <message>
        <source>Drag from the centre out</source>
        <translation>Arrastra desde el centro hacia fuera</translation>
    </message>
    <message>
        <source>Ellipse</source>
        <translation>Elipse</translation>
    </message>
    <message>
        <source>Drag out its bounding box</source>
        <translation>Arrastra el rectángulo que la contiene</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Muelle</translation>
    </message>
    <message>
        <source>Drag from a body to another body or to a point</source>
        <translation>Arrastra desde un cuerpo hasta otro cuerpo o hasta un punto</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Pasador</translation>
    </message>
    <message>
        <source>Click on a body to hinge it to the body below or the world</source>
        <translation>Haz clic en un cuerpo para articularlo al cuerpo de debajo o al mundo</translation>
    </message>
    <message>
        <source>Rod</source>
        <translation>Varilla</translation>
    </message>
    <message>
        <source>%1 (%2): %3</source>
        <translation>%1 (%2): %3</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulación</translation>
    </message>
    <message>
        <source>&amp;Compare Soft with Rigid…</source>
        <translation>&amp;Comparar blando con rígido…</translation>
    </message>
    <message>
        <source>Run the selected soft body rigid and soft for a few seconds and show how far apart they drift</source>
        <translation>Simular el cuerpo blando seleccionado como rígido y como blando durante unos segundos y mostrar cuánto se separan</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>E&amp;jemplos</translation>
    </message>
    <message>
        <source>Run controls</source>
        <translation>Controles de ejecución</translation>
    </message>
    <message>
        <source>Play or pause</source>
        <translation>Iniciar o pausar</translation>
    </message>
    <message>
        <source>Step once</source>
        <translation>Avanzar un paso</translation>
    </message>
    <message>
        <source>Reset to the last Play</source>
        <translation>Reiniciar al último inicio</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Velocidad:</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Simulation speed</source>
        <translation>Velocidad de la simulación</translation>
    </message>
    <message>
        <source>Simulated seconds per real second</source>
        <translation>Segundos simulados por segundo real</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Herramientas</translation>
    </message>
    <message>
        <source>Drawing tools</source>
        <translation>Herramientas de dibujo</translation>
    </message>
    <message>
        <source>%1 tool</source>
        <translation>Herramienta %1</translation>
    </message>
    <message>
        <source>Attributes</source>
        <translation>Atributos</translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation>Tiempo simulado</translation>
    </message>
    <message>
        <source>Kinetic, potential and elastic energy</source>
        <translation>Energía cinética, potencial y elástica</translation>
    </message>
    <message>
        <source>Kinetic energy K, gravitational potential energy U (from y = 0) and elastic energy of the springs</source>
        <translation>Energía cinética K, energía potencial gravitatoria U (desde y = 0) y energía elástica de los muelles</translation>
    </message>
    <message>
        <source>Total energy</source>
        <translation>Energía total</translation>
    </message>
    <message>
        <source>Total momentum</source>
        <translation>Cantidad de movimiento total</translation>
    </message>
    <message>
        <source>Collision count</source>
        <translation>Número de colisiones</translation>
    </message>
    <message>
        <source>Soft bodies</source>
        <translation>Cuerpos blandos</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sin título</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Abrir escena</translation>
    </message>
    <message>
        <source>Impetus scenes (*.json);;All files (*)</source>
        <translation>Escenas de Impetus (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>The default scene is shown instead.</source>
        <translation>En su lugar se muestra la escena predeterminada.</translation>
    </message>
    <message>
        <source>An empty scene is shown instead.</source>
        <translation>En su lugar se muestra una escena vacía.</translation>
    </message>
    <message>
        <source>The current scene is unchanged.</source>
        <translation>La escena actual no cambia.</translation>
    </message>
    <message>
        <source>Cannot open scene</source>
        <translation>No se puede abrir la escena</translation>
    </message>
    <message>
        <source>“%1” could not be opened. %2</source>
        <translation>No se pudo abrir «%1». %2</translation>
    </message>
    <message numerus="yes">
        <source>…and %n more.</source>
        <translation>
            <numerusform>…y %n más.</numerusform>
            <numerusform>…y %n más.</numerusform>
        </translation>
    </message>
    <message>
        <source>The simulation blew up</source>
        <translation>La simulación ha explotado</translation>
    </message>
    <message>
        <source>Body “%1” got a position or velocity that is not a finite number by t = %2 s.</source>
        <translation>El cuerpo «%1» tiene, hacia t = %2 s, una posición o velocidad que no es un número finito.</translation>
    </message>
    <message>
        <source>The run stopped at the last finite state. The time step is too large for the stiffest spring or the fastest motion in the scene. Press Reset (R) to go back to where you pressed Play, or Undo (Ctrl+Z); then try a smaller time step or a softer spring.</source>
        <translation>La ejecución se detuvo en el último estado finito. El paso de tiempo es demasiado grande para el muelle más rígido o el movimiento más rápido de la escena. Pulsa Reiniciar (R) para volver al punto en que pulsaste Iniciar, o Deshacer (Ctrl+Z); después prueba un paso de tiempo menor o un muelle más blando.</translation>
    </message>
    <message>
        <source>Cannot save scene</source>
        <translation>No se puede guardar la escena</translation>
    </message>
    <message>
        <source>The scene could not be saved to “%1”. Nothing was overwritten.</source>
        <translation>No se pudo guardar la escena en «%1». No se ha sobrescrito nada.</translation>
    </message>
    <message>
        <source>Save Scene</source>
        <translation>Guardar escena</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved.</source>
        <translation>«%1» tiene cambios sin guardar.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>¿Guardarlos antes de continuar?</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausar</translation>
    </message>
    <message>
        <source>Pause the simulation (Space)</source>
        <translation>Pausar la simulación (Espacio)</translation>
    </message>
    <message>
        <source>Running %1 rigid and soft…</source>
        <translation>Simulando %1 rígido y blando…</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;th align=right&gt;t (s)&lt;/th&gt;&lt;th align=right&gt;distance (m)&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;th align=right&gt;t (s)&lt;/th&gt;&lt;th align=right&gt;distancia (m)&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>Soft against rigid</source>
        <translation>Blando frente a rígido</translation>
    </message>
    <message>
        <source>&lt;p&gt;How far the centre of mass of &lt;b&gt;%1&lt;/b&gt; run soft (%2 ellipses, %3 per m²) drifts from the same body run rigid, over the next %4 s:&lt;/p&gt;&lt;p&gt;RMS %5 m, largest %6 m at t = %7 s.&lt;/p&gt;%8</source>
        <translation>&lt;p&gt;Cuánto se aleja el centro de masas de &lt;b&gt;%1&lt;/b&gt; simulado como blando (%2 elipses, %3 por m²) del mismo cuerpo simulado como rígido, durante los próximos %4 s:&lt;/p&gt;&lt;p&gt;Valor eficaz %5 m, máximo %6 m en t = %7 s.&lt;/p&gt;%8</translation>
    </message>
    <message>
        <source>%1 — %2 substeps per step</source>
        <translation>%1 — %2 subpasos por paso</translation>
    </message>
    <message>
        <source>One step per step: the grids are stable at this time step.</source>
        <translation>Un subpaso por paso: las cuadrículas son estables con este paso de tiempo.</translation>
    </message>
    <message>
        <source>%1[*] — Impetus</source>
        <translation>%1[*] — Impetus</translation>
    </message>
    <message>
        <source>t = %L1 s</source>
        <translation>t = %L1 s</translation>
    </message>
    <message>
        <source>K = %L1 J  U = %L2 J  elastic = %L3 J</source>
        <translation>K = %L1 J  U = %L2 J  elástica = %L3 J</translation>
    </message>
    <message>
        <source>E = %L1 J</source>
        <translation>E = %L1 J</translation>
    </message>
    <message>
        <source>p = (%L1, %L2) kg·m/s</source>
        <translation>p = (%L1; %L2) kg·m/s</translation>
    </message>
    <message>
        <source>Collisions: %L1</source>
        <translation>Colisiones: %L1</translation>
    </message>
    <message>
        <source>%1: %L2/m² (auto)</source>
        <translation>%1: %L2/m² (automático)</translation>
    </message>
    <message>
        <source>%1: %L2/m²</source>
        <translation>%1: %L2/m²</translation>
    </message>
    <message>
        <source>Step Back</source>
        <translation>Paso atrás</translation>
    </message>
    <message>
        <source>Go back one time step along the timeline (←)</source>
        <translation>Retroceder un paso de tiempo en la línea de tiempo (←)</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Regla</translation>
    </message>
    <message>
        <source>Click two points, or drag: the distance in metres; snaps to body centres and corners</source>
        <translation>Haz clic en dos puntos o arrastra: la distancia en metros; se ajusta a los centros y esquinas de los cuerpos</translation>
    </message>
    <message>
        <source>Protractor</source>
        <translation>Transportador</translation>
    </message>
    <message>
        <source>Click the vertex, then a point on each arm: the angle in degrees</source>
        <translation>Haz clic en el vértice y luego en un punto de cada lado: el ángulo en grados</translation>
    </message>
    <message>
        <source>&amp;Vectors</source>
        <translation>&amp;Vectores</translation>
    </message>
    <message>
        <source>&amp;Velocity</source>
        <translation>&amp;Velocidad</translation>
    </message>
    <message>
        <source>Arrows of each body&apos;s velocity</source>
        <translation>Flechas de la velocidad de cada cuerpo</translation>
    </message>
    <message>
        <source>&amp;Acceleration</source>
        <translation>&amp;Aceleración</translation>
    </message>
    <message>
        <source>Arrows of each body&apos;s acceleration, net force / mass</source>
        <translation>Flechas de la aceleración de cada cuerpo, fuerza neta / masa</translation>
    </message>
    <message>
        <source>&amp;Net Force</source>
        <translation>Fuerza &amp;neta</translation>
    </message>
    <message>
        <source>Arrows of the net force on each body</source>
        <translation>Flechas de la fuerza neta sobre cada cuerpo</translation>
    </message>
    <message>
        <source>&amp;Force Parts</source>
        <translation>&amp;Fuerzas por separado</translation>
    </message>
    <message>
        <source>Arrows of gravity, springs, drag, contact normal and friction forces and joint forces</source>
        <translation>Flechas de la gravedad, los muelles, el rozamiento del aire, las fuerzas normales y de rozamiento de los contactos y las fuerzas de las uniones</translation>
    </message>
    <message>
        <source>&amp;Momentum</source>
        <translation>&amp;Momento lineal</translation>
    </message>
    <message>
        <source>Arrows of each body&apos;s momentum</source>
        <translation>Flechas del momento lineal de cada cuerpo</translation>
    </message>
    <message>
        <source>&amp;Longer Arrows</source>
        <translation>Flechas más &amp;largas</translation>
    </message>
    <message>
        <source>Double the length of every arrow (the legend gives the scale)</source>
        <translation>Duplicar la longitud de cada flecha (la leyenda indica la escala)</translation>
    </message>
    <message>
        <source>&amp;Shorter Arrows</source>
        <translation>Flechas más &amp;cortas</translation>
    </message>
    <message>
        <source>Halve the length of every arrow (the legend gives the scale)</source>
        <translation>Reducir a la mitad la longitud de cada flecha (la leyenda indica la escala)</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation>&amp;Trayectorias</translation>
    </message>
    <message>
        <source>Draw the path of each body&apos;s centre of mass, with a dot every few steps</source>
        <translation>Dibujar la trayectoria del centro de masas de cada cuerpo, con un punto cada pocos pasos</translation>
    </message>
    <message>
        <source>Trail &amp;Dots Every</source>
        <translation>&amp;Puntos de trayectoria cada</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n paso</numerusform>
            <numerusform>%n pasos</numerusform>
        </translation>
    </message>
    <message>
        <source>Vectors and Trails for &amp;Selected Bodies Only</source>
        <translation>Vectores y trayectorias solo de los cuerpos &amp;seleccionados</translation>
    </message>
    <message>
        <source>Draw arrows and trails only for the bodies selected</source>
        <translation>Dibujar flechas y trayectorias solo para los cuerpos seleccionados</translation>
    </message>
    <message>
        <source>New &amp;Graph</source>
        <translation>Nuevo &amp;gráfico</translation>
    </message>
    <message>
        <source>Plot a quantity of the selected body against time, or against another quantity</source>
        <translation>Representar una magnitud del cuerpo seleccionado frente al tiempo o frente a otra magnitud</translation>
    </message>
    <message>
        <source>Step back once</source>
        <translation>Retroceder un paso</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Sonda</translation>
    </message>
    <message>
        <source>Click a body to read its position, velocity, energies and collisions as it moves</source>
        <translation>Haz clic en un cuerpo para leer su posición, velocidad, energías y colisiones mientras se mueve</translation>
    </message>
    <message>
        <source>E&amp;xplain</source>
        <translation>E&amp;xplicar</translation>
    </message>
    <message>
        <source>&amp;Separating Axes</source>
        <translation>&amp;Ejes separadores</translation>
    </message>
    <message>
        <source>Show how the collision test treats the two selected bodies, axis by axis (N: next, P: previous, Esc: close)</source>
        <translation>Mostrar cómo trata la prueba de colisión a los dos cuerpos seleccionados, eje por eje (N: siguiente, P: anterior, Esc: cerrar)</translation>
    </message>
    <message>
        <source>Collision Inspector</source>
        <translation>Inspector de colisiones</translation>
    </message>
    <message>
        <source>&amp;Collision Inspector</source>
        <translation>&amp;Inspector de colisiones</translation>
    </message>
    <message>
        <source>List the collisions of the run; click one to see its impulse worked out</source>
        <translation>Listar las colisiones de la simulación; haz clic en una para ver el cálculo de su impulso</translation>
    </message>
    <message>
        <source>Energy &amp;Ledger</source>
        <translation>&amp;Balance de energía</translation>
    </message>
    <message>
        <source>Chart where the energy goes: what each cause has taken out, stacked over time</source>
        <translation>Representar adónde va la energía: lo que ha retirado cada causa, apilado a lo largo del tiempo</translation>
    </message>
    <message>
        <source>Energy Ledger</source>
        <translation>Balance de energía</translation>
    </message>
    <message>
        <source>Trace Point</source>
        <translation>Trazar punto</translation>
    </message>
    <message>
        <source>Click a point on a body to draw the path it takes (a wheel&apos;s rim: a cycloid); click it again, or Esc, to stop</source>
        <translation>Haga clic en un punto de un cuerpo para dibujar su trayectoria (en el borde de una rueda: una cicloide); otro clic o Esc la detiene</translation>
    </message>
    <message>
        <source>At t = %1 s the solver let the centre of “%2” into “%3”; it was put back at the surface.</source>
        <translation>En t = %1 s la simulación dejó entrar el centro de «%2» en «%3»; se devolvió a la superficie.</translation>
    </message>
    <message numerus="yes">
        <source>%n more such body pair(s) in the same steps.</source>
        <translation>
            <numerusform>%n par de cuerpos más así en los mismos pasos.</numerusform>
            <numerusform>%n pares de cuerpos más así en los mismos pasos.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>impetus::view::PaceIndicator</name>
    <message>
        <source>Speed against real time</source>
        <translation>Velocidad respecto al tiempo real</translation>
    </message>
    <message>
        <source>Computing a step…</source>
        <translation>Calculando un paso…</translation>
    </message>
    <message>
        <source>Running at %1× real time</source>
        <translation>A %1× el tiempo real</translation>
    </message>
    <message>
        <source>Running at %1× real time (speed set to %2×)</source>
        <translation>A %1× el tiempo real (velocidad elegida: %2×)</translation>
    </message>
    <message>
        <source>Simulated time runs at %1× real time, slower than the %2× asked for.</source>
        <translation>El tiempo simulado avanza a %1× el tiempo real, más despacio que los %2× pedidos.</translation>
    </message>
    <message>
        <source>Step (→) is computing one time step in the background. The canvas shows it when it is done; the window keeps working meanwhile.</source>
        <translation>Paso (→) está calculando un paso de tiempo en segundo plano. El lienzo lo mostrará al terminar; mientras tanto la ventana sigue funcionando.</translation>
    </message>
    <message>
        <source>No step has been computed yet; the first one has taken %1 s so far.</source>
        <translation>Aún no se ha calculado ningún paso; el primero lleva %1 s.</translation>
    </message>
    <message>
        <source>One step (%1 ms of simulated time) takes %2 ms to compute; at %3× it may take at most %4 ms.</source>
        <translation>Un paso (%1 ms de tiempo simulado) tarda %2 ms en calcularse; a %3× puede tardar como mucho %4 ms.</translation>
    </message>
    <message>
        <source>The last step took %1 ms to compute.</source>
        <translation>El último paso tardó %1 ms en calcularse.</translation>
    </message>
    <message>
        <source>The steps being computed now have taken %1 s so far.</source>
        <translation>Los pasos que se están calculando llevan %1 s.</translation>
    </message>
    <message>
        <source>The last step — bodies: %1, contacts: %2, impacts: %3. Solving the contacts and joints took %4 ms of its %5 ms.</source>
        <translation>El último paso — cuerpos: %1, contactos: %2, choques: %3. Resolver los contactos y las uniones llevó %4 ms de sus %5 ms.</translation>
    </message>
    <message>
        <source>Soft bodies split each step into %1 substeps. %2</source>
        <translation>Los cuerpos blandos dividen cada paso en %1 subpasos. %2</translation>
    </message>
    <message>
        <source>To make steps faster: use fewer bodies, or give soft bodies fewer ellipses per m².</source>
        <translation>Para que los pasos sean más rápidos: usa menos cuerpos o da a los cuerpos blandos menos elipses por m².</translation>
    </message>
    <message>
        <source>The steps themselves are fast enough: the computer was busy with something else for a moment.</source>
        <translation>Los pasos en sí son bastante rápidos: el ordenador estuvo ocupado con otra cosa un momento.</translation>
    </message>
    <message>
        <source>To keep up: use fewer bodies, give soft bodies fewer ellipses per m², make the time step larger, or choose a lower speed.</source>
        <translation>Para no quedarse atrás: usa menos cuerpos, da a los cuerpos blandos menos elipses por m², aumenta el paso de tiempo o elige una velocidad menor.</translation>
    </message>
</context>
<context>
    <name>impetus::view::ProjectorMode</name>
    <message>
        <source>&amp;Projector Mode</source>
        <translation>&amp;Modo proyector</translation>
    </message>
    <message>
        <source>Full screen, large text and readouts, thick lines and strong contrast for a projector (F11)</source>
        <translation>Pantalla completa, texto y lecturas grandes, líneas gruesas y mucho contraste para el proyector (F11)</translation>
    </message>
</context>
<context>
    <name>impetus::view::PropertyPane</name>
    <message>
        <source>Attributes</source>
        <translation>Atributos</translation>
    </message>
    <message>
        <source>Shown item</source>
        <translation>Elemento mostrado</translation>
    </message>
    <message>
        <source>Selection note</source>
        <translation>Nota sobre la selección</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>Unit: %1</source>
        <translation>Unidad: %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>World settings</source>
        <translation>Ajustes del mundo</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>Change gravity</source>
        <translation>Cambiar la gravedad</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrador</translation>
    </message>
    <message>
        <source>Explicit Euler (euler)</source>
        <translation>Euler explícito (euler)</translation>
    </message>
    <message>
        <source>Semi-implicit Euler (semi-implicit-euler)</source>
        <translation>Euler semiimplícito (semi-implicit-euler)</translation>
    </message>
    <message>
        <source>Runge–Kutta 4 (rk4)</source>
        <translation>Runge-Kutta 4 (rk4)</translation>
    </message>
    <message>
        <source>Time step</source>
        <translation>Paso de tiempo</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>Change time step</source>
        <translation>Cambiar el paso de tiempo</translation>
    </message>
    <message>
        <source>Time step must be from %1 s to %2 s (got %3 s).</source>
        <translation>El paso de tiempo debe estar entre %1 s y %2 s (se ha dado %3 s).</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Rozamiento del aire</translation>
    </message>
    <message>
        <source>N·s/m</source>
        <translation>N·s/m</translation>
    </message>
    <message>
        <source>Change drag</source>
        <translation>Cambiar el rozamiento del aire</translation>
    </message>
    <message>
        <source>Body attributes</source>
        <translation>Atributos del cuerpo</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Resize body</source>
        <translation>Cambiar el tamaño del cuerpo</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radio</translation>
    </message>
    <message>
        <source>Semi-axis x</source>
        <translation>Semieje x</translation>
    </message>
    <message>
        <source>Semi-axis y</source>
        <translation>Semieje y</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Anchura</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Altura</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vértices</translation>
    </message>
    <message>
        <source>Polygon vertices in the body&apos;s own frame, in metres</source>
        <translation>Vértices del polígono en el sistema de referencia del cuerpo, en metros</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>Add vertex</source>
        <translation>Añadir vértice</translation>
    </message>
    <message>
        <source>Insert a vertex halfway along the edge after the current vertex</source>
        <translation>Insertar un vértice en la mitad del lado que sigue al vértice actual</translation>
    </message>
    <message>
        <source>Remove vertex</source>
        <translation>Quitar vértice</translation>
    </message>
    <message>
        <source>Remove the current vertex</source>
        <translation>Quitar el vértice actual</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Posición</translation>
    </message>
    <message>
        <source>Move body</source>
        <translation>Mover el cuerpo</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Rotate body</source>
        <translation>Girar el cuerpo</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Change velocity</source>
        <translation>Cambiar la velocidad</translation>
    </message>
    <message>
        <source>Angular velocity</source>
        <translation>Velocidad angular</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>Change angular velocity</source>
        <translation>Cambiar la velocidad angular</translation>
    </message>
    <message>
        <source>Mass given as</source>
        <translation>Masa dada como</translation>
    </message>
    <message>
        <source>Choose whether you give the density or the mass; the other follows from the area</source>
        <translation>Elige si das la densidad o la masa; la otra se deduce del área</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Densidad</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Masa</translation>
    </message>
    <message>
        <source>kg/m²</source>
        <translation>kg/m²</translation>
    </message>
    <message>
        <source>Change density</source>
        <translation>Cambiar la densidad</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Change mass</source>
        <translation>Cambiar la masa</translation>
    </message>
    <message>
        <source>Moment of inertia</source>
        <translation>Momento de inercia</translation>
    </message>
    <message>
        <source>kg·m²</source>
        <translation>kg·m²</translation>
    </message>
    <message>
        <source>Restitution</source>
        <translation>Restitución</translation>
    </message>
    <message>
        <source>(0–1)</source>
        <translation>(0–1)</translation>
    </message>
    <message>
        <source>Change restitution</source>
        <translation>Cambiar la restitución</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Rozamiento</translation>
    </message>
    <message>
        <source>(≥ 0)</source>
        <translation>(≥ 0)</translation>
    </message>
    <message>
        <source>Change friction</source>
        <translation>Cambiar el rozamiento</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Fijo</translation>
    </message>
    <message>
        <source>A fixed body has infinite mass: it moves only with the velocity it is given</source>
        <translation>Un cuerpo fijo tiene masa infinita: solo se mueve con la velocidad que se le da</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Color</translation>
    </message>
    <message>
        <source>Soft body</source>
        <translation>Cuerpo blando</translation>
    </message>
    <message>
        <source>Simulate the body as a grid of small ellipses joined by springs</source>
        <translation>Simular el cuerpo como una cuadrícula de pequeñas elipses unidas por muelles</translation>
    </message>
    <message>
        <source>Ellipses per square metre</source>
        <translation>Elipses por metro cuadrado</translation>
    </message>
    <message>
        <source>A number greater than 0, or “auto”</source>
        <translation>Un número mayor que 0, o «auto»</translation>
    </message>
    <message>
        <source>a number or “auto”</source>
        <translation>un número o «auto»</translation>
    </message>
    <message>
        <source>Ellipses per m²</source>
        <translation>Elipses por m²</translation>
    </message>
    <message>
        <source>1/m²</source>
        <translation>1/m²</translation>
    </message>
    <message>
        <source>Soft grid</source>
        <translation>Cuadrícula blanda</translation>
    </message>
    <message>
        <source>Soft stiffness</source>
        <translation>Rigidez (blando)</translation>
    </message>
    <message>
        <source>N/m</source>
        <translation>N/m</translation>
    </message>
    <message>
        <source>Change soft stiffness</source>
        <translation>Cambiar la rigidez del cuerpo blando</translation>
    </message>
    <message>
        <source>Soft damping</source>
        <translation>Amortiguación (blando)</translation>
    </message>
    <message>
        <source>Change soft damping</source>
        <translation>Cambiar la amortiguación del cuerpo blando</translation>
    </message>
    <message>
        <source>Spring attributes</source>
        <translation>Atributos del muelle</translation>
    </message>
    <message>
        <source>Body A</source>
        <translation>Cuerpo A</translation>
    </message>
    <message>
        <source>Anchor A</source>
        <translation>Anclaje A</translation>
    </message>
    <message>
        <source>Move spring end</source>
        <translation>Mover el extremo del muelle</translation>
    </message>
    <message>
        <source>Anchor A (body frame)</source>
        <translation>Anclaje A (sistema del cuerpo)</translation>
    </message>
    <message>
        <source>Body B</source>
        <translation>Cuerpo B</translation>
    </message>
    <message>
        <source>Anchor B</source>
        <translation>Anclaje B</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <translation>Constante elástica</translation>
    </message>
    <message>
        <source>Change spring stiffness</source>
        <translation>Cambiar la constante elástica</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Amortiguación</translation>
    </message>
    <message>
        <source>Change spring damping</source>
        <translation>Cambiar la amortiguación del muelle</translation>
    </message>
    <message>
        <source>Rest length</source>
        <translation>Longitud en reposo</translation>
    </message>
    <message>
        <source>Change rest length</source>
        <translation>Cambiar la longitud en reposo</translation>
    </message>
    <message>
        <source>Joint attributes</source>
        <translation>Atributos de la unión</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Hinge</source>
        <translation>Bisagra</translation>
    </message>
    <message>
        <source>Move hinge</source>
        <translation>Mover la bisagra</translation>
    </message>
    <message>
        <source>Move rod end</source>
        <translation>Mover el extremo de la varilla</translation>
    </message>
    <message>
        <source>Hinge (world point)</source>
        <translation>Bisagra (punto del mundo)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Longitud</translation>
    </message>
    <message>
        <source>The size or density is too extreme to simulate (mass %1 kg, moment of inertia %2 kg·m²).</source>
        <translation>El tamaño o la densidad son demasiado extremos para simularlos (masa %1 kg, momento de inercia %2 kg·m²).</translation>
    </message>
    <message>
        <source>A rod needs two different ends: both anchors are at the same point.</source>
        <translation>Una varilla necesita dos extremos distintos: los dos anclajes están en el mismo punto.</translation>
    </message>
    <message>
        <source>Name: a body needs a name.</source>
        <translation>Nombre: un cuerpo necesita un nombre.</translation>
    </message>
    <message>
        <source>Name: another body is already called “%1”; names must be unique.</source>
        <translation>Nombre: otro cuerpo ya se llama «%1»; los nombres deben ser únicos.</translation>
    </message>
    <message>
        <source>Rename body</source>
        <translation>Renombrar el cuerpo</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>%1: “%2” is neither a number nor “auto”.</source>
        <translation>%1: «%2» no es un número ni «auto».</translation>
    </message>
    <message>
        <source>%1 must be a number greater than 0, or “auto” (got %2).</source>
        <translation>%1 debe ser un número mayor que 0, o «auto» (se ha dado %2).</translation>
    </message>
    <message>
        <source>Change soft density</source>
        <translation>Cambiar la densidad de elipses</translation>
    </message>
    <message>
        <source>Vertex %1 %2</source>
        <translation>Vértice %1 %2</translation>
    </message>
    <message>
        <source>Move vertex</source>
        <translation>Mover el vértice</translation>
    </message>
    <message>
        <source>Vertices: choose the vertex to remove in the table first.</source>
        <translation>Vértices: elige primero en la tabla el vértice que quieres quitar.</translation>
    </message>
    <message>
        <source>Vertices: the shape is refused: %1.</source>
        <translation>Vértices: la forma no es válida: %1.</translation>
    </message>
    <message>
        <source>Give mass instead of density</source>
        <translation>Dar la masa en lugar de la densidad</translation>
    </message>
    <message>
        <source>Give density instead of mass</source>
        <translation>Dar la densidad en lugar de la masa</translation>
    </message>
    <message>
        <source>Change integrator</source>
        <translation>Cambiar el integrador</translation>
    </message>
    <message>
        <source>Fix body</source>
        <translation>Fijar el cuerpo</translation>
    </message>
    <message>
        <source>Free body</source>
        <translation>Soltar el cuerpo</translation>
    </message>
    <message>
        <source>Turn on soft mode</source>
        <translation>Activar el modo blando</translation>
    </message>
    <message>
        <source>Turn off soft mode</source>
        <translation>Desactivar el modo blando</translation>
    </message>
    <message>
        <source>Body Colour</source>
        <translation>Color del cuerpo</translation>
    </message>
    <message>
        <source>Change colour</source>
        <translation>Cambiar el color</translation>
    </message>
    <message>
        <source>(world)</source>
        <translation>(mundo)</translation>
    </message>
    <message numerus="yes">
        <source>%n items selected; the pane shows the first.</source>
        <translation>
            <numerusform>%n elemento seleccionado; el panel muestra el primero.</numerusform>
            <numerusform>%n elementos seleccionados; el panel muestra el primero.</numerusform>
        </translation>
    </message>
    <message>
        <source>World</source>
        <translation>Mundo</translation>
    </message>
    <message>
        <source>Body “%1”</source>
        <translation>Cuerpo «%1»</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Círculo</translation>
    </message>
    <message>
        <source>Ellipse</source>
        <translation>Elipse</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Rectángulo</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polígono</translation>
    </message>
    <message>
        <source>Current colour %1; press to choose another</source>
        <translation>Color actual %1; pulsa para elegir otro</translation>
    </message>
    <message>
        <source>Vertex %1 %2 = %3 m</source>
        <translation>Vértice %1 %2 = %3 m</translation>
    </message>
    <message>
        <source>Spring %1</source>
        <translation>Muelle %1</translation>
    </message>
    <message>
        <source>Anchor B (body frame)</source>
        <translation>Anclaje B (sistema del cuerpo)</translation>
    </message>
    <message>
        <source>Anchor B (world point)</source>
        <translation>Anclaje B (punto del mundo)</translation>
    </message>
    <message>
        <source>Pin joint %1</source>
        <translation>Pasador %1</translation>
    </message>
    <message>
        <source>Rod joint %1</source>
        <translation>Varilla %1</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Pasador</translation>
    </message>
    <message>
        <source>Rod</source>
        <translation>Varilla</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number.</source>
        <translation>%1: «%2» no es un número.</translation>
    </message>
    <message>
        <source>%1 must be a finite number (got %2).</source>
        <translation>%1 debe ser un número finito (se ha dado %2).</translation>
    </message>
    <message>
        <source>%1 must be greater than 0 (got %2).</source>
        <translation>%1 debe ser mayor que 0 (se ha dado %2).</translation>
    </message>
    <message>
        <source>%1 must be 0 or greater (got %2).</source>
        <translation>%1 debe ser 0 o mayor (se ha dado %2).</translation>
    </message>
    <message>
        <source>%1 must be between 0 and 1 (got %2).</source>
        <translation>%1 debe estar entre 0 y 1 (se ha dado %2).</translation>
    </message>
    <message>
        <source>%L1 ellipses at %L2 per m², chosen by “auto” on this computer</source>
        <translation>%L1 elipses a %L2 por m², elegidas por «auto» en este ordenador</translation>
    </message>
    <message>
        <source>%L1 ellipses at %L2 per m²</source>
        <translation>%L1 elipses a %L2 por m²</translation>
    </message>
    <message>
        <source>Lock note</source>
        <translation>Nota de bloqueo</translation>
    </message>
    <message>
        <source>Soft damping ratio ζ</source>
        <translation>Razón de amortiguación ζ (blando)</translation>
    </message>
    <message>
        <source>Change soft damping ratio</source>
        <translation>Cambiar la razón de amortiguación del cuerpo blando</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Avisos</translation>
    </message>
    <message>
        <source>Show vectors</source>
        <translation>Mostrar vectores</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Aceleración</translation>
    </message>
    <message>
        <source>Net force</source>
        <translation>Fuerza neta</translation>
    </message>
    <message>
        <source>Force parts</source>
        <translation>Fuerzas por separado</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Momento lineal</translation>
    </message>
    <message>
        <source>Show %1 arrows of this body</source>
        <translation>Mostrar las flechas de %1 de este cuerpo</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Aviso: %1</translation>
    </message>
    <message>
        <source>Use a time step of %1 ms</source>
        <translation>Usar un paso de tiempo de %1 ms</translation>
    </message>
    <message>
        <source>Use the time step that holds this spring</source>
        <translation>Usar el paso de tiempo que soporta este muelle</translation>
    </message>
</context>
<context>
    <name>impetus::view::SatExplainer</name>
    <message>
        <source>Separating axes: A = %1 (blue), B = %2 (orange)</source>
        <translation>Ejes separadores: A = %1 (azul), B = %2 (naranja)</translation>
    </message>
    <message>
        <source>Convex pieces: %1 of A and %2 of B (pair %3 of %4)</source>
        <translation>Piezas convexas: %1 de A y %2 de B (par %3 de %4)</translation>
    </message>
    <message>
        <source>Method: SAT over the face normals of both polygons: %1 candidate axes, %2 tested.</source>
        <translation>Método: SAT sobre las normales de los lados de ambos polígonos: %1 ejes candidatos, %2 probados.</translation>
    </message>
    <message>
        <source>Method: the polygon&apos;s face normals, then the feature of the polygon closest to the circle&apos;s centre (a face or a corner): a circle has no faces of its own.</source>
        <translation>Método: las normales de los lados del polígono y después el elemento del polígono más cercano al centro del círculo (un lado o un vértice): un círculo no tiene lados propios.</translation>
    </message>
    <message>
        <source>Method: two circles need a single axis, the line through their centres.</source>
        <translation>Método: dos círculos necesitan un solo eje, la recta que pasa por sus centros.</translation>
    </message>
    <message>
        <source>Method: GJK and EPA. An ellipse has no faces, so there are no axes to test: GJK finds the distance between the shapes, and when they overlap EPA finds the depth and the direction of least penetration (to 0.001 mm).</source>
        <translation>Método: GJK y EPA. Una elipse no tiene lados, así que no hay ejes que probar: GJK halla la distancia entre las formas y, cuando se solapan, EPA halla la profundidad y la dirección de menor penetración (con precisión de 0,001 mm).</translation>
    </message>
    <message>
        <source>Result: normal %1, depth %2 mm at %3.</source>
        <translation>Resultado: normal %1, profundidad %2 mm en %3.</translation>
    </message>
    <message>
        <source>Result: the shapes are apart.</source>
        <translation>Resultado: las formas están separadas.</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>normal of face %1 of %2</source>
        <translation>normal del lado %1 de %2</translation>
    </message>
    <message>
        <source>from corner %1 of %2 to the circle&apos;s centre</source>
        <translation>del vértice %1 de %2 al centro del círculo</translation>
    </message>
    <message>
        <source>line of centres, from A to B</source>
        <translation>línea de los centros, de A a B</translation>
    </message>
    <message>
        <source>Axis %1 of %2: %3, direction %4</source>
        <translation>Eje %1 de %2: %3, dirección %4</translation>
    </message>
    <message>
        <source>Projections: %1 from %2 to %3 mm, %4 from %5 to %6 mm</source>
        <translation>Proyecciones: %1 de %2 a %3 mm, %4 de %5 a %6 mm</translation>
    </message>
    <message>
        <source>Overlap on this axis: %1 mm</source>
        <translation>Solapamiento en este eje: %1 mm</translation>
    </message>
    <message>
        <source>Gap on this axis: %1 mm</source>
        <translation>Separación en este eje: %1 mm</translation>
    </message>
    <message>
        <source>This axis separates the shapes: no contact. The search stops here (%1 of %2 axes tested).</source>
        <translation>Este eje separa las formas: no hay contacto. La búsqueda termina aquí (%1 de %2 ejes probados).</translation>
    </message>
    <message>
        <source>This is the axis of least overlap.</source>
        <translation>Este es el eje de menor solapamiento.</translation>
    </message>
    <message>
        <source>Separated: axis %1 leaves a gap of %2 mm, so the pair is not in contact.</source>
        <translation>Separados: el eje %1 deja una separación de %2 mm, así que el par no está en contacto.</translation>
    </message>
    <message>
        <source>Least overlap: axis %1 (%2), %3 mm</source>
        <translation>Menor solapamiento: eje %1 (%2), %3 mm</translation>
    </message>
    <message>
        <source>B&apos;s best face is better by less than the tolerance, so A&apos;s face stays the reference: resting stacks do not swap faces on rounding noise.</source>
        <translation>El mejor lado de B es mejor por menos que la tolerancia, así que el lado de A sigue siendo la referencia: las pilas en reposo no cambian de lado por el ruido de redondeo.</translation>
    </message>
    <message>
        <source>Minimum translation vector: %1 mm along %2 (moves B off A)</source>
        <translation>Vector mínimo de traslación: %1 mm a lo largo de %2 (aparta B de A)</translation>
    </message>
    <message>
        <source>Reference face (green): face %1 of %2; incident face (purple): face %3 of %4</source>
        <translation>Lado de referencia (verde): lado %1 de %2; lado incidente (morado): lado %3 de %4</translation>
    </message>
    <message>
        <source>The incident face lies beyond the reference face&apos;s ends (corner to corner): one point.</source>
        <translation>El lado incidente queda más allá de los extremos del lado de referencia (vértice contra vértice): un punto.</translation>
    </message>
    <message>
        <source>Clipped to the reference face&apos;s sides: %1 points; kept (touching): %2</source>
        <translation>Recortado a los límites laterales del lado de referencia: %1 puntos; conservados (en contacto): %2</translation>
    </message>
    <message>
        <source>Contact point %1: %2 m, separation %3 mm</source>
        <translation>Punto de contacto %1: %2 m, separación %3 mm</translation>
    </message>
    <message>
        <source>N: next axis   P: previous   Esc: close</source>
        <translation>N: eje siguiente   P: anterior   Esc: cerrar</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <extracomment>A point or a direction: its x and y. Where the decimal separator is a comma, separate them with a semicolon: (0,600; 0,800).</extracomment>
        <translation>(%1; %2)</translation>
    </message>
</context>
<context>
    <name>impetus::view::SceneDocument</name>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ejecución</translation>
    </message>
</context>
<context>
    <name>impetus::view::TimelineBar</name>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>Time along the run</source>
        <translation>Tiempo a lo largo de la ejecución</translation>
    </message>
    <message>
        <source>Drag to go back to any moment of the run; Play goes on from there</source>
        <translation>Arrastra para volver a cualquier momento de la ejecución; Iniciar continúa desde ahí</translation>
    </message>
    <message>
        <source>Time shown</source>
        <translation>Tiempo mostrado</translation>
    </message>
    <message>
        <source>t = %1 s of %2 s</source>
        <translation>t = %1 s de %2 s</translation>
    </message>
</context>
</TS>
